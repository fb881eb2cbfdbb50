// SPDX-License-Identifier: GPL-3.0-or-later
// render/render_request.h: a picture asked for in words becomes RenderOptions, or the usage
// error that names the first wrong flag and its value.
#include "render/render_request.h"

#include <gtest/gtest.h>

namespace roomcad {
namespace {

Plan room() {
  Plan plan;
  plan.site.cells = {8, 6};
  plan.walls.push_back(Wall{.id = "s", .from = {1, 1}, .to = {7, 1}});
  return plan;
}

/// The command's request with `set` applied.
template <class Set>
RenderRequest asking(Set&& set) {
  RenderRequest request;
  set(request);
  return request;
}

TEST(RenderRequest, TheDefaultsMakeTheCommandsOptions) {
  const Result<RenderOptions> options = make_render_options(RenderRequest{}, room());
  ASSERT_TRUE(options.ok()) << options.message();
  EXPECT_EQ(options->width, 1280);
  EXPECT_EQ(options->height, 720);
  EXPECT_FALSE(options->camera.has_value());
}

TEST(RenderRequest, AWrongFlagIsAUsageErrorNamingItAndItsValue) {
  const auto refused = [](RenderRequest request, const std::string& words) {
    const Result<RenderOptions> options = make_render_options(request, room());
    ASSERT_FALSE(options.ok()) << words;
    EXPECT_EQ(options.code(), Code::usage_error) << options.message();
    EXPECT_NE(options.message().find(words), std::string::npos) << options.message();
  };
  refused(asking([](RenderRequest& r) { r.camera = "nowhere"; }), "--camera 'nowhere'");
  refused(asking([](RenderRequest& r) { r.eye = "1,2,3"; }), "--eye and --target go together");
  refused(asking([](RenderRequest& r) { r.eye = "1,2", r.target = "0,0,0"; }), "--eye '1,2'");
  refused(asking([](RenderRequest& r) { r.width = 100000, r.height = 100000; }),
          "--width 100000 x --height 100000");
  refused(asking([](RenderRequest& r) { r.shading = "bogus"; }), "--shading 'bogus'");
  refused(asking([](RenderRequest& r) { r.parts = "walls,roof"; }), "'roof'");
  refused(asking([](RenderRequest& r) { r.grid = "maybe"; }), "--grid 'maybe'");
}

TEST(RenderRequest, TheFirstWrongFlagIsTheOneNamed) {
  const Result<RenderOptions> options = make_render_options(
      asking([](RenderRequest& r) { r.projection = "fisheye", r.shading = "bogus"; }), room());
  ASSERT_FALSE(options.ok());
  EXPECT_NE(options.message().find("--projection 'fisheye'"), std::string::npos)
      << options.message();
}

TEST(RenderRequest, ARangeTheFlagsCannotHoldFailsTheOptionsCheck) {
  const Result<RenderOptions> options =
      make_render_options(asking([](RenderRequest& r) { r.width = 0; }), room());
  ASSERT_FALSE(options.ok());
  EXPECT_NE(options.message().find("render: "), std::string::npos) << options.message();
  EXPECT_NE(options.message().find(" 0 x 720"), std::string::npos) << options.message();
}

}  // namespace
}  // namespace roomcad
