// SPDX-License-Identifier: GPL-3.0-or-later
// Render options that would exhaust memory or time are refused, naming the option and value.
#include <string>

#include <gtest/gtest.h>

#include "render/renderer.h"

namespace roomcad {
namespace {

/// "" for good options; else the message, after checking that the code is usage_error.
std::string problem(const RenderOptions& options) {
  const Status status = check_render_options(options);
  if (status) return "";
  EXPECT_EQ(status.code(), Code::usage_error);
  return status.message();
}

TEST(RenderLimits, AcceptsTheLargestFramesAndMaps) {
  EXPECT_EQ(problem({.width = 8192, .height = 8192, .ssaa = 2}), "");
  EXPECT_EQ(problem({.width = 16384, .height = 4096}), "");
  EXPECT_EQ(problem({.width = 4096, .height = 4096, .ssaa = 4}), "");
  EXPECT_EQ(problem({.shadow_resolution = kMaxShadowResolution}), "");
  EXPECT_EQ(problem({.threads = kMaxThreads}), "");
}

TEST(RenderLimits, RefusesTooManyPixelsSamplesTexelsOrThreads) {
  EXPECT_EQ(problem({.width = 16384, .height = 16384}),
            "width x height is 16384 x 16384 = 268435456 pixels; at most 67108864 are rendered");
  EXPECT_EQ(problem({.width = 16385, .height = 1}),
            "width x height is 16385 x 1; each must be 1 to 16384");
  EXPECT_EQ(problem({.width = 8192, .height = 8192, .ssaa = 4}),
            "width x height x ssaa^2 is 8192 x 8192 x 16 = 1073741824 samples; at most 268435456");
  EXPECT_EQ(problem({.shadow_resolution = 8193}),
            "shadow resolution is 8193; it must be 1 to 8192");
  EXPECT_EQ(problem({.threads = 257}), "threads is 257; it must be 0 (all cores) to 256");
}

}  // namespace
}  // namespace roomcad
