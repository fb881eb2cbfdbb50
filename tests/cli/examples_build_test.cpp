// Every bundled example plan builds, and its wall solid passes --check.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/run_command.h"

namespace roomcad {
namespace {

std::vector<std::filesystem::path> example_plans() {
  std::vector<std::filesystem::path> plans;
  const auto root = test::source_dir() / "examples";
  if (!std::filesystem::exists(root)) return plans;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".json") continue;
    if (test::read_bytes(entry.path()).find("\"roomcad-plan\"") == std::string::npos) continue;
    plans.push_back(entry.path());
  }
  std::sort(plans.begin(), plans.end());
  return plans;
}

// Plans of version 2 geometry (levels, sloped tops, arcs, shapes, slabs) that the build does
// not read yet: it does from the general path on (issue 15), and they join the loop below
// with it. Each is checked to be a version 2 plan, so the list hides no version 1 plan.
const char* const kVersion2Plans[] = {
    "sweethome3d/1-BedroomApartment.json",         "sweethome3d/2-BedroomHouseWithBasement.json",
    "sweethome3d/3-BedroomHouseWithAttic.json",    "sweethome3d/3-BedroomHouseWithMezzanine.json",
    "sweethome3d/4-BedroomHouse.json",             "sweethome3d/Sample.json",
    "sweethome3d/arif-home.json",                  "sweethome3d/arif-putra-pertama-1.json",
    "version2/two-storey.json"};

bool is_listed_version2(const std::filesystem::path& plan) {
  const std::string relative =
      std::filesystem::relative(plan, test::source_dir() / "examples").generic_string();
  for (const char* listed : kVersion2Plans)
    if (relative == listed) {
      EXPECT_NE(test::read_bytes(plan).find("\"version\": 2"), std::string::npos) << plan;
      return true;
    }
  return false;
}

// The curated plans (examples/*.json) validate and build as they are; the imported homes
// (examples/sweethome3d/) carry the validation errors of their sources, so they are built
// with --force. Every one must give a wall solid that passes --check.
TEST(BuildCommand, EveryExamplePlanBuildsAndChecks) {
  const auto plans = example_plans();
  if (plans.empty()) GTEST_SKIP() << "no example plans under examples/";
  test::TempDir dir;
  for (const auto& plan : plans) {
    if (is_listed_version2(plan)) continue;
    const bool curated = plan.parent_path() == test::source_dir() / "examples";
    const auto out = dir / (plan.stem().string() + ".obj");
    std::vector<std::string> args{"build", plan.string(), "-o", out.string(), "--check"};
    if (!curated) args.push_back("--force");
    const auto r = test::run_roomcad(args);
    EXPECT_EQ(r.status, 0) << plan << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("check: ok"), std::string::npos) << plan << "\n" << r.out;
    EXPECT_TRUE(std::filesystem::exists(out)) << plan;
  }
}

}  // namespace
}  // namespace roomcad
