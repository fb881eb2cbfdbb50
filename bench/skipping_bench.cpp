// SPDX-License-Identifier: GPL-3.0-or-later
// What skipping saves: frame times at 1920 x 1080 with each culling switch on and off
// (FaceCull none / back faces / visibility pre-pass, frustum culling of clusters on / off), on
// the 10 x 10 grid of rooms and on examples/house.json, each seen from outside and from inside
// a room (inside, most of the scene is behind the camera: that is where frustum culling pays).
// Shadows are off so that the times are the colour pass, the only pass the switches touch.
// Counters: triangles submitted, triangles left on screen, triangles the pre-pass skipped.
#include <benchmark/benchmark.h>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/plan_json.h"
#include "render/renderer.h"
#include "solid/build_model.h"
#include "testing/grid_plan.h"

namespace roomcad {
namespace {

struct View {
  const char* name;
  Scene scene;
  std::optional<Camera> camera;  ///< nullopt: the default framing (iso, from outside)
};

Scene flatten_plan(const Plan& plan) { return flatten_model(build_model(plan), Parts{}); }

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
    Result<Plan> read = read_plan_file(ROOMCAD_SOURCE_DIR "/examples/house.json");
    if (!read) throw std::runtime_error("skipping_bench: examples/house.json does not load");
    const Scene house = flatten_plan(read.value());
    return std::array<View, 4>{{
        {"grid10_outside", grid, std::nullopt},
        {"grid10_inside", grid, camera_at({1.0, 1.0, 1.6}, {8.0, 2.6, 1.4})},
        {"house_outside", house, read->cameras.front()},
        {"house_inside", house, camera_at({6.0, 2.0, 1.6}, {18.0, 5.0, 1.2})},
    }};
  }();
  return all;
}

/// Args: view (index into views()), cull (0 none, 1 back faces, 2 visibility), frustum (0 off,
/// 1 on).
void BM_Skipping(benchmark::State& state) {
  const View& view = views()[static_cast<std::size_t>(state.range(0))];
  constexpr FaceCull culls[] = {FaceCull::none, FaceCull::back_faces, FaceCull::visibility};
  const RenderOptions options{.width = 1920,
                              .height = 1080,
                              .camera = view.camera,
                              .shadows = ShadowFilter::off,
                              .cull = culls[state.range(1)],
                              .cull_frustum = state.range(2) == 1,
                              .threads = 2};
  FrameBuffers out;
  RenderStats stats;
  for (auto _ : state) render_scene(view.scene, options, out, &stats);
  state.SetLabel(view.name);
  state.counters["triangles"] = static_cast<double>(stats.triangles);
  state.counters["screen_triangles"] = static_cast<double>(stats.screen_triangles);
  state.counters["prepass_skipped"] = static_cast<double>(stats.culled_triangles);
}
BENCHMARK(BM_Skipping)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.3);

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
