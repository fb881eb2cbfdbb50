// SPDX-License-Identifier: GPL-3.0-or-later
// Depth precision: reversed-Z float keeps surfaces 1 cm apart apart at 1 km.
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "scene_support.h"

namespace roomcad {
namespace {

/// Two 40 m squares facing the camera, `gap` metres apart, 1 km away. The far one comes first
/// in scene order, so where depths tie the far one would stay: any tie shows as its id.
int pixels_showing_far_square(double gap) {
  Model m;
  m.objects = {"far", "near"};
  auto square = [&](double y, int object) {
    test::add_face(m.walls,
                   {{-20.0, y, -20.0}, {20.0, y, -20.0}, {20.0, y, 20.0}, {-20.0, y, 20.0}}, object,
                   FaceKind::wall_face, test::kWallColor);
  };
  square(1000.0 + gap, 0);  // faces -y, towards the eye: wound counter-clockwise from -y
  square(1000.0, 1);
  const RenderOptions options{.width = 64,
                              .height = 64,
                              .camera = test::look_from({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.5),
                              .shading = ShadingMode::unlit,
                              .shadows = ShadowFilter::off};
  FrameBuffers out;
  render_model(m, options, out);
  int far = 0, empty = 0;
  for (int id : out.objects.ids) {
    far += id == 0;
    empty += id == -1;
  }
  EXPECT_EQ(empty, 0) << "the squares fill the view";
  return far;
}

TEST(Render, ReversedZResolvesOneCentimetreAtOneKilometre) {
  EXPECT_EQ(pixels_showing_far_square(0.01), 0);
  EXPECT_EQ(pixels_showing_far_square(0.001), 0);  // and 1 mm, measured, with margin
}

TEST(Render, DepthBufferHoldsViewDistanceInMetres) {
  Model m;
  m.objects = {"q"};
  test::add_face(
      m.walls, {{-20.0, 50.0, -20.0}, {20.0, 50.0, -20.0}, {20.0, 50.0, 20.0}, {-20.0, 50.0, 20.0}},
      0, FaceKind::wall_face, test::kWallColor);
  const RenderOptions options{
      .width = 16, .height = 16, .camera = test::look_from({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 20.0)};
  FrameBuffers out;
  render_model(m, options, out);
  for (float d : out.depth.values) EXPECT_NEAR(d, 50.0, 1e-3);
}

}  // namespace
}  // namespace roomcad
