// SPDX-License-Identifier: GPL-3.0-or-later
// The renderer against the exact reference (CGAL ray casts): object ids away from silhouettes,
// windows seen straight on, and triangles crossing the near plane.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/renderer.h"
#include "scene_support.h"

namespace roomcad {
namespace {

using test::RayCaster;

/// Walls of three objects standing on a floor (object 0), and a two-sided door leaf.
Model make_rooms() {
  Model m;
  m.objects = {"floor", "w1", "w2", "w3", "leaf"};
  test::add_floor(m.floor, {-2.0, -2.0}, {12.0, 10.0}, 0);
  test::add_box(m.walls, {0.0, 0.0, 0.0}, {8.0, 0.25, 2.8}, 1);
  test::add_box(m.walls, {0.0, 0.25, 0.0}, {0.25, 6.0, 2.8}, 2);
  test::add_box(m.walls, {4.0, 3.0, 0.0}, {4.3, 7.0, 2.2}, 3, {40, 90, 200});
  test::add_face(m.fixtures, {{6.0, 4.0, 0.0}, {6.9, 4.5, 0.0}, {6.9, 4.5, 2.1}, {6.0, 4.0, 2.1}},
                 4, FaceKind::door, {90, 60, 30});
  return m;
}

/// The reference object id at every pixel centre.
std::vector<int> reference_ids(const Model& m, const CameraMatrices& cam, int w, int h) {
  const RayCaster caster({&m.walls, &m.floor, &m.fixtures});
  std::vector<int> ids(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const test::PixelRay r = test::pixel_ray(cam, w, h, x, y);
      ids[static_cast<std::size_t>(y) * w + x] = caster.first_object(r.origin, r.direction);
    }
  return ids;
}

/// Renders and compares ids on every pixel more than one pixel from a reference silhouette.
/// @return the number of pixels compared.
int compare_ids(const Model& m, const RenderOptions& options) {
  FrameBuffers out;
  render_model(m, options, out);
  const CameraMatrices cam = frame_camera(flatten_model(m, options.parts), options);
  const std::vector<int> ref = reference_ids(m, cam, options.width, options.height);
  int compared = 0;
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x) {
      if (!test::is_uniform_around(ref, options.width, options.height, x, y, 1)) continue;
      ++compared;
      EXPECT_EQ(out.objects.at(x, y), ref[static_cast<std::size_t>(y) * options.width + x])
          << "pixel " << x << "," << y;
    }
  return compared;
}

TEST(Render, IdsMatchRayCastingAwayFromSilhouettesDefaultCamera) {
  const int compared = compare_ids(make_rooms(), RenderOptions{.width = 160, .height = 120});
  EXPECT_GT(compared, 160 * 120 / 2);
}

TEST(Render, IdsMatchRayCastingFromInsideARoomAndOrthographic) {
  const Camera inside = test::look_from({6.0, 2.0, 1.6}, {3.0, 5.0, 1.0});
  EXPECT_GT(compare_ids(make_rooms(), RenderOptions{.width = 160, .height = 120, .camera = inside}),
            160 * 120 / 2);
  const Camera ortho = test::look_from({12.0, -6.0, 9.0}, {4.0, 3.0, 0.0}, 50.0, 14.0);
  EXPECT_GT(compare_ids(make_rooms(), RenderOptions{.width = 120, .height = 160, .camera = ortho}),
            120 * 160 / 2);
}

TEST(Render, ATriangleCrossingTheNearPlaneIsDrawnClipped) {
  Model m;  // one big floor quad (two triangles) reaching far behind the eye
  m.objects = {"floor"};
  test::add_floor(m.floor, {-500.0, -500.0}, {500.0, 500.0}, 0);
  const RenderOptions options{
      .width = 120, .height = 90, .camera = test::look_from({0.0, 0.0, 1.0}, {0.0, 10.0, 0.2})};
  FrameBuffers out;
  render_model(m, options, out);
  int floor_pixels = 0;
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x) floor_pixels += out.objects.at(x, y) == 0;
  EXPECT_GT(floor_pixels, options.width * options.height / 2);  // below the horizon
  EXPECT_GT(compare_ids(m, options), options.width * options.height * 3 / 4);
}

/// A 6 m wall (y in [0, 0.25]) with two 1 m high windows, built from boxes around them.
struct WindowWall {
  Model model;
  std::vector<std::array<double, 4>> windows{{1.0, 2.0, 1.0, 2.0}, {3.5, 5.0, 1.0, 2.0}};
};

WindowWall make_window_wall() {
  WindowWall w;
  w.model.objects = {"wall"};
  const double t = 0.25;
  SolidMesh& m = w.model.walls;
  test::add_box(m, {0.0, 0.0, 0.0}, {1.0, t, 3.0}, 0);
  test::add_box(m, {2.0, 0.0, 0.0}, {3.5, t, 3.0}, 0);
  test::add_box(m, {5.0, 0.0, 0.0}, {6.0, t, 3.0}, 0);
  for (const auto& win : w.windows) {
    test::add_box(m, {win[0], 0.0, 0.0}, {win[1], t, win[2]}, 0);
    test::add_box(m, {win[0], 0.0, win[3]}, {win[1], t, 3.0}, 0);
  }
  return w;
}

TEST(Render, OrthographicFrontViewShowsBackgroundThroughEveryWindow) {
  const WindowWall wall = make_window_wall();
  const Scene scene = flatten_model(wall.model);
  const double aspect = 2.0;
  RenderOptions options{.width = 240,
                        .height = 120,
                        .shading = ShadingMode::unlit,
                        .shadows = ShadowFilter::off,
                        .background = {0, 0, 255}};
  options.camera =
      frame_view(scene.bounds, ViewPreset::front, Projection::orthographic, 50.0, aspect);
  FrameBuffers out;
  render_scene(scene, options, out);
  const CameraMatrices cam = frame_camera(scene, options);
  const double pixel = options.camera->view_height / options.height;  // metres per pixel
  int window_pixels = 0, wall_pixels = 0;
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x) {
      const test::PixelRay r = test::pixel_ray(cam, options.width, options.height, x, y);
      const double s = -r.origin.y / r.direction.y;  // where the ray meets the front, y = 0
      const double wx = r.origin.x + s * r.direction.x, wz = r.origin.z + s * r.direction.z;
      auto inside = [&](double x0, double x1, double z0, double z1, double margin) {
        return wx > x0 + margin && wx < x1 - margin && wz > z0 + margin && wz < z1 - margin;
      };
      bool in_window = false, near_window = false;
      for (const auto& win : wall.windows) {
        in_window |= inside(win[0], win[1], win[2], win[3], pixel);
        near_window |= inside(win[0], win[1], win[2], win[3], -pixel);
      }
      const std::uint8_t* c = out.color.at(x, y);
      const Color seen{c[0], c[1], c[2]};
      if (in_window) {
        ++window_pixels;
        EXPECT_EQ(seen, options.background) << "window pixel " << x << "," << y;
      } else if (!near_window && inside(0.0, 6.0, 0.0, 3.0, pixel)) {
        ++wall_pixels;
        EXPECT_EQ(seen, test::kWallColor) << "wall pixel " << x << "," << y;
      }
    }
  EXPECT_GT(window_pixels, 400);
  EXPECT_GT(wall_pixels, 4000);
}

}  // namespace
}  // namespace roomcad
