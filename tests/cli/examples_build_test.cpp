// SPDX-License-Identifier: GPL-3.0-or-later
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

// The curated plans (examples/*.json) validate and build as they are; the imported homes
// (examples/sweethome3d/) carry the validation errors of their sources, so they are built
// with --force. Every one must give a wall solid that passes --check.
TEST(BuildCommand, EveryExamplePlanBuildsAndChecks) {
  const auto plans = example_plans();
  if (plans.empty()) GTEST_SKIP() << "no example plans under examples/";
  test::TempDir dir;
  for (const auto& plan : plans) {
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
