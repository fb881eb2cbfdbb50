// SPDX-License-Identifier: GPL-3.0-or-later
// Culling only skips work: `roomcad render` draws the same picture with every --cull mode
// (none, back, visibility) and --frustum-cull on or off, on every bundled example; Makarov &
// Safin's pre-pass never drops a face the picture shows. Bad values exit 2.
#include <filesystem>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;
using test::run_roomcad;

TEST(Cull, NoCullingSwitchChangesAnyExamplePicture) {
  test::TempDir dir;
  // The default first: every other picture is compared with it.
  const std::pair<const char*, const char*> switches[] = {
      {"back", "on"}, {"visibility", "on"}, {"none", "on"}, {"back", "off"}, {"none", "off"}};
  for (const fs::path& plan : test::example_plans()) {
    const std::string name = plan.stem().string();
    std::string reference;
    for (const auto& [cull, frustum] : switches) {
      const auto out = dir / (name + "-" + cull + "-" + frustum + ".png");
      const auto r =
          run_roomcad({"render", plan.string(), "--width", "240", "--height", "160", "--ssaa", "2",
                       "--cull", cull, "--frustum-cull", frustum, "--stats", "-o", out.string()});
      ASSERT_EQ(r.status, 0) << name << " --cull " << cull << ": " << r.err;
      if (std::string(cull) == "visibility") {
        EXPECT_EQ(r.err.find("\"culled_triangles\": 0,"), std::string::npos) << name << r.err;
      }
      const std::string picture = test::read_bytes(out);
      if (reference.empty()) {
        reference = picture;
        EXPECT_GT(reference.size(), 1000u) << name;
      }
      EXPECT_TRUE(picture == reference)
          << name << " --cull " << cull << " --frustum-cull " << frustum << " differs";
    }
  }
}

TEST(Cull, UnknownModeExitsTwo) {
  test::TempDir dir;
  const auto r = run_roomcad({"render", (test::source_dir() / "examples/studio.json").string(),
                              "--cull", "sometimes", "-o", (dir / "p.png").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(test::failure_code(r), Code::usage_error);
  EXPECT_NE((r.out + r.err).find("--cull"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "p.png"));
}

TEST(Cull, UnknownFrustumSwitchExitsTwo) {
  test::TempDir dir;
  const auto r = run_roomcad({"render", (test::source_dir() / "examples/studio.json").string(),
                              "--frustum-cull", "maybe", "-o", (dir / "p.png").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(test::failure_code(r), Code::usage_error);
  EXPECT_NE((r.out + r.err).find("--frustum-cull"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "p.png"));
}

}  // namespace
}  // namespace roomcad
