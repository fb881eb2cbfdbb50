// SPDX-License-Identifier: GPL-3.0-or-later
// Culling only skips work: `roomcad render` draws the same picture with every --cull mode
// (none, back, portals, visibility) and --frustum-cull on or off, on every bundled example; Makarov
// & Safin's pre-pass never drops a face the picture shows. Bad values exit 2.
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
  const std::pair<const char*, const char*> switches[] = {{"back", "on"},    {"visibility", "on"},
                                                          {"portals", "on"}, {"none", "on"},
                                                          {"back", "off"},   {"none", "off"}};
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

// From inside a room the portal walk reaches some cells and submits fewer triangles; the
// picture is the one back-face culling draws.
TEST(Cull, PortalsFromInsideARoomSkipTheRoomsItCannotSee) {
  test::TempDir dir;
  const std::string plan = (test::source_dir() / "examples/house.json").string();
  std::string pictures[2];
  const char* culls[2] = {"back", "portals"};
  for (int k = 0; k < 2; ++k) {
    const auto out = dir / (std::string(culls[k]) + ".png");
    const auto r =
        run_roomcad({"render", plan, "--eye", "6,2,1.6", "--target", "18,5,1.2", "--width", "320",
                     "--height", "180", "--cull", culls[k], "--stats", "-o", out.string()});
    ASSERT_EQ(r.status, 0) << r.err;
    pictures[k] = test::read_bytes(out);
    if (k == 1) {
      EXPECT_EQ(r.err.find("\"cells_visited\": 0,"), std::string::npos) << r.err;
      EXPECT_EQ(r.err.find("\"drawn_triangles\": 0}"), std::string::npos) << r.err;
    }
  }
  EXPECT_GT(pictures[0].size(), 1000u);
  EXPECT_TRUE(pictures[0] == pictures[1]);
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
