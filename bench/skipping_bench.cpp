// SPDX-License-Identifier: GPL-3.0-or-later
// What skipping saves: frame times at 1920 x 1080 with each culling switch on and off
// (FaceCull none / back faces / portal walk / portal walk and visibility pre-pass, frustum
// culling of clusters on / off), on the 10 x 10 grid of rooms and on examples/house.json, each
// seen from outside and from inside a room (inside, most of the scene is behind the camera:
// that is where frustum culling pays). Shadows are off so that the times are the colour pass,
// the only pass the switches touch. Counters: triangles submitted, triangles left on screen,
// triangles the pre-pass skipped, cells the portal walk reached and triangles it submitted.
//
// BM_Inside: the same eye inside a room of models of every size (the 10 x 10 and 70 x 70
// grids, examples/house.json, the six-storey tower, arif-putra-pertama-1), shadows off and on
// (the maps kept between frames, as the window keeps them).
#include <benchmark/benchmark.h>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/plan_json.h"
#include "render/portal_walk.h"
#include "render/renderer.h"
#include "render/scene_cells.h"
#include "solid/build_model.h"
#include "testing/grid_plan.h"
#include "testing/tower_plan.h"

namespace roomcad {
namespace {

struct View {
  const char* name;
  Scene scene;
  std::optional<Camera> camera;  ///< nullopt: the default framing (iso, from outside)
};

Scene flatten_plan(const Plan& plan) {
  return flatten_model(build_model(plan, BuildOptions{.cells = true}), Parts{});
}

Plan read_example(const char* path) {
  Result<Plan> read = read_plan_file(std::string(ROOMCAD_SOURCE_DIR "/") + path);
  if (!read) throw std::runtime_error(std::string("skipping_bench: ") + path + " does not load");
  return std::move(read).value();
}

Camera camera_at(Vec3 eye, Vec3 target) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.fov_deg = 60.0;
  return c;
}

/// The four views, built once. Inside: eye height 1.6 m in the grid's corner room looking
/// east through its door, and in the house's south-west room looking along the day side.
const std::array<View, 4>& views() {
  static const std::array<View, 4> all = [] {
    const Scene grid = flatten_plan(samples::make_grid_plan({.n = 10}));
    const Plan plan = read_example("examples/house.json");
    const Scene house = flatten_plan(plan);
    return std::array<View, 4>{{
        {"grid10_outside", grid, std::nullopt},
        {"grid10_inside", grid, camera_at({1.0, 1.0, 1.6}, {8.0, 2.6, 1.4})},
        {"house_outside", house, plan.cameras.front()},
        {"house_inside", house, camera_at({6.0, 2.0, 1.6}, {18.0, 5.0, 1.2})},
    }};
  }();
  return all;
}

constexpr FaceCull kCulls[] = {FaceCull::none, FaceCull::back_faces, FaceCull::portals,
                               FaceCull::visibility};

void count(benchmark::State& state, const View& view, const RenderStats& stats) {
  state.SetLabel(view.name);
  state.counters["triangles"] = static_cast<double>(stats.triangles);
  state.counters["screen_triangles"] = static_cast<double>(stats.screen_triangles);
  state.counters["prepass_skipped"] = static_cast<double>(stats.culled_triangles);
  state.counters["cells_visited"] = static_cast<double>(stats.cells_visited);
  state.counters["drawn_triangles"] = static_cast<double>(stats.drawn_triangles);
}

/// Args: view (index into views()), cull (0 none, 1 back faces, 2 portals, 3 visibility),
/// frustum (0 off, 1 on).
void BM_Skipping(benchmark::State& state) {
  const View& view = views()[static_cast<std::size_t>(state.range(0))];
  const RenderOptions options{.width = 1920,
                              .height = 1080,
                              .camera = view.camera,
                              .shadows = ShadowFilter::off,
                              .cull = kCulls[state.range(1)],
                              .cull_frustum = state.range(2) == 1,
                              .threads = 2};
  FrameBuffers out;
  RenderStats stats;
  for (auto _ : state) render_scene(view.scene, options, out, &stats);
  count(state, view, stats);
}
BENCHMARK(BM_Skipping)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.3);

/// An eye 1.6 m over the floor of the first cell (largest first) the walk can start from,
/// looking east and a little down.
Camera inside_camera(const Scene& scene) {
  std::vector<const Cell*> cells;
  for (const Cell& c : scene.cells->cells.cells) cells.push_back(&c);
  auto area = [](const Cell* c) {
    return (c->bounds.high[0] - c->bounds.low[0]) * (c->bounds.high[1] - c->bounds.low[1]);
  };
  std::stable_sort(cells.begin(), cells.end(),
                   [&](const Cell* a, const Cell* b) { return area(a) > area(b); });
  for (const Cell* c : cells) {
    const Vec3 eye{(c->bounds.low[0] + c->bounds.high[0]) / 2,
                   (c->bounds.low[1] + c->bounds.high[1]) / 2, c->floor_z + 1.6};
    const Camera cam = camera_at(eye, {eye.x + 3.0, eye.y + 1.0, eye.z - 0.2});
    const CameraMatrices m =
        rebase_camera(make_camera_matrices(cam, scene.bounds, 16.0 / 9.0), scene.origin);
    if (walk_portals(scene, m)) return cam;
  }
  throw std::runtime_error("skipping_bench: no cell to stand in");
}

/// The inside views: the grids' from the eye, the others from inside_camera.
const std::array<View, 5>& inside_views() {
  static const std::array<View, 5> all = [] {
    const Camera grid_eye = camera_at({2.0, 2.0, 1.6}, {3.5, 3.0, 1.5});
    Scene tower = flatten_plan(samples::make_tower_plan({}));
    Scene arif = flatten_plan(read_example("examples/sweethome3d/arif-putra-pertama-1.json"));
    Scene house = flatten_plan(read_example("examples/house.json"));
    const Camera tower_eye = inside_camera(tower), arif_eye = inside_camera(arif),
                 house_eye = inside_camera(house);
    return std::array<View, 5>{{
        {"grid10_inside", flatten_plan(samples::make_grid_plan({.n = 10})), grid_eye},
        {"grid70_inside", flatten_plan(samples::make_grid_plan({.n = 70})), grid_eye},
        {"house_inside", std::move(house), house_eye},
        {"tower_inside", std::move(tower), tower_eye},
        {"arif_inside", std::move(arif), arif_eye},
    }};
  }();
  return all;
}

/// Args: view (index into inside_views()), cull (1 back faces, 2 portals, 3 visibility),
/// shadows (0 off, 1 pcf with the maps kept between frames).
void BM_Inside(benchmark::State& state) {
  const View& view = inside_views()[static_cast<std::size_t>(state.range(0))];
  const RenderOptions options{
      .width = 1920,
      .height = 1080,
      .camera = view.camera,
      .shadows = state.range(2) == 1 ? ShadowFilter::pcf : ShadowFilter::off,
      .cull = kCulls[state.range(1)],
      .threads = 2,
      .reuse_shadow_maps = true};
  FrameBuffers out;
  RenderStats stats;
  for (auto _ : state) render_scene(view.scene, options, out, &stats);
  count(state, view, stats);
}
BENCHMARK(BM_Inside)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.3);

/// What the walk costs before the first frame, on the 70 x 70 grid: finding the cells from the
/// plan (exact 2D booleans; 9,940 walls), and filing the scene's triangles under them.
void BM_FindCells(benchmark::State& state) {
  const Plan plan = samples::make_grid_plan({.n = 70});
  std::size_t cells = 0;
  for (auto _ : state) cells = find_model_cells(plan).cells.size();
  state.counters["cells"] = static_cast<double>(cells);
}
BENCHMARK(BM_FindCells)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.3);

void BM_IndexCells(benchmark::State& state) {
  const Plan plan = samples::make_grid_plan({.n = 70});
  const Scene scene = flatten_model(build_model(plan), Parts{});
  const Cells cells = find_model_cells(plan);
  for (auto _ : state) benchmark::DoNotOptimize(index_cells(cells, scene));
  state.counters["triangles"] = static_cast<double>(scene.triangle_count());
}
BENCHMARK(BM_IndexCells)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.3);

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
