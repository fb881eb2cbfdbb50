// SPDX-License-Identifier: GPL-3.0-or-later
// Makarov & Safin's visible-surface pre-pass: finds exactly the triangles the z-buffer shows (none
// dropped, none extra), and culling with it leaves the picture unchanged.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>
#include <vector>

#include <tbb/task_arena.h>

#include "render/detail/geometry_pass.h"
#include "render/renderer.h"
#include "render/visibility.h"
#include "scene_support.h"
#include "solid/build_model.h"
#include "testing/grid_plan.h"

namespace roomcad::test {
namespace {

/// The scene triangles the rasteriser's id buffer shows at width x height samples.
std::set<std::uint32_t> z_buffer_ids(const Scene& scene, const CameraMatrices& cam, int width,
                                     int height, int tile_size) {
  detail::BinnedTriangles bins;
  detail::run_geometry_pass(scene,
                            {.uniform_view_projection = glm::mat4(cam.view_projection),
                             .width = width,
                             .height = height,
                             .tile_size = tile_size,
                             .cull_back_faces = true},
                            bins);
  std::set<std::uint32_t> ids;
  for (int tile = 0; tile < bins.tile_count(); ++tile) {
    RasterTarget t = detail::tile_rectangle(bins, tile);
    const std::size_t n = static_cast<std::size_t>(t.x1 - t.x0) * (t.y1 - t.y0);
    std::vector<float> depth(n, 0.f);
    std::vector<std::uint32_t> id(n, kNoTriangle);
    t.depth = depth.data();
    t.ids = id.data();
    detail::rasterize_tile(bins, tile, t);
    for (const std::uint32_t i : id)
      if (i != kNoTriangle) ids.insert(bins.at(i).triangle);
  }
  return ids;
}

/// Checks the pre-pass against the z-buffer: the same set of triangles, at the given tiling.
/// @return the number of triangles shown.
std::size_t expect_equal(const Scene& scene, const Camera& camera, int width, int height,
                         int tile_size = 64) {
  const CameraMatrices cam =
      rebase_camera(make_camera_matrices(camera, scene.bounds, static_cast<double>(width) / height),
                    scene.origin);
  const std::set<std::uint32_t> shown = z_buffer_ids(scene, cam, width, height, tile_size);
  const VisibilityResult v = find_visible_faces(scene, {cam, width, height, tile_size});
  std::size_t missing = 0, extra = 0;
  for (std::uint32_t t = 0; t < scene.triangle_count(); ++t) {
    if (shown.count(t) && !v.visible[t]) ++missing;
    if (!shown.count(t) && v.visible[t]) ++extra;
  }
  EXPECT_EQ(missing, 0u) << "of " << shown.size() << " shown triangles";
  EXPECT_EQ(extra, 0u) << "beyond " << shown.size() << " shown triangles";
  EXPECT_EQ(v.visible_count, shown.size());
  EXPECT_LT(v.visible_count, scene.triangle_count());  // something is skipped
  return shown.size();
}

Scene grid_scene(int n) {
  const Plan plan = samples::make_grid_plan({.n = n});
  return flatten_model(build_model(plan), Parts{});
}

/// Boxes on a jittered 6 x 6 lattice (never touching), random heights, on a floor.
Scene random_boxes(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Model m;
  add_face_properties(m.walls);
  add_face_properties(m.floor);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const glm::dvec3 lo{2.0 * i + 0.4 * u(rng), 2.0 * j + 0.4 * u(rng), 0.0};
      add_box(m.walls, lo, lo + glm::dvec3(0.5 + u(rng), 0.5 + u(rng), 0.3 + 3.0 * u(rng)),
              i * 6 + j);
    }
  add_floor(m.floor, {-1.0, -1.0}, {13.0, 13.0}, 99);
  return flatten_model(m, Parts{});
}

TEST(Visibility, FindsExactlyTheTrianglesTheZBufferShows) {
  const Scene grid = grid_scene(3);
  const glm::dvec3 centre = (low_corner(grid.bounds) + high_corner(grid.bounds)) / 2.0;
  const struct {
    const char* name;
    Camera camera;
  } views[] = {
      {"iso", frame_view(grid.bounds, ViewPreset::iso, Projection::perspective, 50.0, 1.5)},
      {"top", frame_view(grid.bounds, ViewPreset::top, Projection::orthographic, 50.0, 1.5)},
      {"front", frame_view(grid.bounds, ViewPreset::front, Projection::perspective, 40.0, 1.5)},
      {"inside", look_from({2.0, 2.0, 1.6}, centre + glm::dvec3(0, 0, 0.5), 70.0)},
  };
  for (const auto& v : views) {
    SCOPED_TRACE(v.name);
    for (const int tile : {64, 128}) {
      SCOPED_TRACE(tile);
      const std::size_t shown = expect_equal(grid, v.camera, 320, 200, tile);
      std::printf("grid 3x3 %s, tiles %d: %zu triangles shown\n", v.name, tile, shown);
    }
  }
}

TEST(Visibility, RandomSceneSetsEqualTheZBuffers) {
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = random_boxes(seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> angle(0.0, 6.283);
    const double a = angle(rng);
    const glm::dvec3 eye{6.0 + 14.0 * std::cos(a), 6.0 + 14.0 * std::sin(a), 6.0};
    const std::size_t shown = expect_equal(s, look_from(eye, {6.0, 6.0, 0.5}, 55.0), 256, 192);
    std::printf("boxes seed %u: %zu triangles shown\n", seed, shown);
  }
}

TEST(Visibility, CullingLeavesThePictureUnchanged) {
  const Scene grid = grid_scene(2);
  RenderOptions options{.width = 200, .height = 150, .shadows = ShadowFilter::hard};
  FrameBuffers plain, culled;
  RenderStats stats;
  render_scene(grid, options, plain);
  options.cull = FaceCull::visibility;
  render_scene(grid, options, culled, &stats);
  EXPECT_GT(stats.culled_triangles, grid.triangle_count() / 4);
  EXPECT_EQ(plain.color.pixels, culled.color.pixels);
  EXPECT_EQ(plain.objects.ids, culled.objects.ids);
}

TEST(Visibility, LightFindsFacesWhollyInShadow) {
  Model m;
  add_face_properties(m.walls);
  add_face_properties(m.floor);
  // A small box under a big slab, lit from straight above: the small box is wholly in shadow.
  add_box(m.walls, {0, 0, 2}, {4, 4, 2.2}, 0);
  add_box(m.walls, {1.5, 1.5, 0}, {2.5, 2.5, 1}, 1);
  const Scene s = flatten_model(m, Parts{});
  Light sun;
  sun.direction = {0, 0, -1};
  const VisibilityResult lit = find_lit_faces(s, sun, 256);
  for (std::size_t t = 0; t < s.triangle_count(); ++t) {
    if (s.objects[t] == 1) {
      EXPECT_EQ(lit.visible[t], 0) << t;
    } else if (s.normals[t].z > 0.5f) {
      EXPECT_EQ(lit.visible[t], 1) << t;
    }
  }
}

TEST(Visibility, SameSetAtAnyThreadCount) {
  const Scene grid = grid_scene(3);
  const Camera cam = frame_view(grid.bounds, ViewPreset::iso, Projection::perspective, 50.0, 1.5);
  const CameraMatrices m = rebase_camera(make_camera_matrices(cam, grid.bounds, 1.5), grid.origin);
  std::vector<std::uint8_t> one, two;
  tbb::task_arena(1).execute([&] { one = find_visible_faces(grid, {m, 300, 200}).visible; });
  tbb::task_arena(2).execute([&] { two = find_visible_faces(grid, {m, 300, 200}).visible; });
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace roomcad::test
