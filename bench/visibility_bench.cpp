// SPDX-License-Identifier: GPL-3.0-or-later
// Makarov & Safin's visibility pre-pass and hidden-line drawings: faces skipped and time saved on
// the bundled examples and on generated grids of rooms (testing/grid_plan.h).
//
// BM_Render/<scene>/<cull>: one 1280 x 720 frame (phong, pcf shadows), cull = back (0) or
// visibility (1); counters: triangles, culled (skipped by the pre-pass), cull_ms (the pre-pass
// itself, inside the frame time), on_screen (triangles set up for the raster),
// shadowed (triangles the pre-pass from the first light finds wholly in shadow).
// BM_PrePass/<scene>: find_visible_faces alone; counters: visible, front_facing, regions,
// crossings (line-triangle crossings computed).
// BM_HiddenLines/<scene>: the isometric line drawing; counters: edges, pieces.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/plan_json.h"
#include "render/line_drawing.h"
#include "render/renderer.h"
#include "render/visibility.h"
#include "solid/build_model.h"
#include "testing/grid_plan.h"

namespace {

using namespace roomcad;

struct BenchScene {
  std::string name;
  Plan plan;
  Model model;
  Scene scene;
};

std::vector<BenchScene> load_scenes() {
  std::vector<BenchScene> out;
  const std::string dir = ROOMCAD_SOURCE_DIR "/examples/";
  for (const char* file : {"studio.json", "flat.json", "house.json", "office.json",
                           "sweethome3d/Sample.json", "sweethome3d/4-BedroomHouse.json"}) {
    Result<Plan> read = read_plan_file(dir + file);
    if (!read) continue;
    out.push_back({std::filesystem::path(file).stem().string(), std::move(read).value(), {}, {}});
  }
  for (const int n : {5, 10, 20}) {
    out.push_back({"grid" + std::to_string(n), samples::make_grid_plan({.n = n}), {}, {}});
  }
  for (BenchScene& s : out) {
    s.model = build_model(s.plan);
    s.scene = flatten_model(s.model, Parts{});
  }
  return out;
}

RenderOptions frame_options(const BenchScene& s, FaceCull cull) {
  RenderOptions o{.width = 1280, .height = 720, .lights = s.plan.lights, .cull = cull};
  if (!s.plan.cameras.empty()) o.camera = s.plan.cameras.front();
  return o;
}

void render_frames(benchmark::State& state, const BenchScene* s, FaceCull cull) {
  const RenderOptions options = frame_options(*s, cull);
  FrameBuffers out;
  RenderStats stats;
  double cull_ms = 0.0;
  for (auto _ : state) {
    render_scene(s->scene, options, out, &stats);
    cull_ms += stats.cull_ms;
  }
  const Light light = s->plan.lights.empty() ? default_light() : s->plan.lights.front();
  const VisibilityResult lit = find_lit_faces(s->scene, light, 1024);
  state.counters["triangles"] = static_cast<double>(s->scene.triangle_count());
  state.counters["culled"] = static_cast<double>(stats.culled_triangles);
  state.counters["cull_ms"] = cull_ms / static_cast<double>(state.iterations());
  state.counters["on_screen"] = static_cast<double>(stats.screen_triangles);
  state.counters["shadowed"] = static_cast<double>(lit.front_facing - lit.visible_count);
}

/// The pre-pass alone, with its work counts (independent of the machine's load).
void run_pre_pass(benchmark::State& state, const BenchScene* s) {
  const RenderOptions options = frame_options(*s, FaceCull::visibility);
  const VisibilityView view{rebase_camera(frame_camera(s->scene, options), s->scene.origin),
                            options.width, options.height};
  VisibilityResult r;
  for (auto _ : state) r = find_visible_faces(s->scene, view);
  state.counters["visible"] = static_cast<double>(r.visible_count);
  state.counters["front_facing"] = static_cast<double>(r.front_facing);
  state.counters["regions"] = static_cast<double>(r.regions);
  state.counters["crossings"] = static_cast<double>(r.crossings);
}

void draw_hidden_lines(benchmark::State& state, const BenchScene* s) {
  const LineView iso = *preset_line_view("iso");
  HiddenLineResult r;
  for (auto _ : state) r = remove_hidden_lines(s->model, Parts{}, iso);
  state.counters["edges"] = static_cast<double>(r.feature_edges);
  state.counters["pieces"] = static_cast<double>(r.pieces);
  state.counters["lines"] = static_cast<double>(r.visible.size() + r.hidden.size());
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  static const std::vector<BenchScene> scenes = load_scenes();
  for (const BenchScene& s : scenes) {
    for (const FaceCull cull : {FaceCull::back_faces, FaceCull::visibility}) {
      benchmark::RegisterBenchmark(
          ("BM_Render/" + s.name + (cull == FaceCull::visibility ? "/visibility" : "/back"))
              .c_str(),
          render_frames, &s, cull)
          ->Unit(benchmark::kMillisecond);
    }
    benchmark::RegisterBenchmark(("BM_PrePass/" + s.name).c_str(), run_pre_pass, &s)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_HiddenLines/" + s.name).c_str(), draw_hidden_lines, &s)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
