// SPDX-License-Identifier: GPL-3.0-or-later
// Window frame times: the viewer (view/viewer.h) at 1280 x 720 on every bundled example, with
// the overlay, as the window draws them while orbiting (each frame a new camera). A frame of
// an edit adds the model rebuild: BM_ViewEditFrame moves a wall one cell and back (the window
// rebuilds the wall groups the edit touched, view/model_cache.h: counters groups and rebuilt;
// the 4-bedroom home is one group, Sample four).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "view/model_cache.h"
#include "view/viewer.h"

namespace roomcad {
namespace {

std::filesystem::path example(const std::string& name) {
  return std::filesystem::path(ROOMCAD_SOURCE_DIR) / "examples" / (name + ".json");
}

Viewer open_viewer(const std::string& name) {
  Result<ViewSession> session = ViewSession::open(example(name));
  if (!session) throw std::runtime_error(session.message());
  return Viewer(std::move(session).value(), ViewerOptions{.width = 1280, .height = 720});
}

InputEvent key(const char* name) {
  InputEvent e;
  e.key = name;
  return e;
}

void BM_ViewOrbitFrame(benchmark::State& state, const std::string& name) {
  Viewer viewer = open_viewer(name);
  viewer.frame();
  for (auto _ : state) {
    viewer.handle(key("a"));  // orbit: the next frame draws again
    benchmark::DoNotOptimize(viewer.frame().pixels.data());
  }
  state.counters["frame_ms"] = viewer.last_frame_ms();
}

void BM_ViewEditFrame(benchmark::State& state, const std::string& name) {
  Viewer viewer = open_viewer(name);
  viewer.handle(key("tab"));  // the first wall
  bool east = true;
  for (auto _ : state) {
    viewer.handle(key(east ? "right" : "left"));
    east = !east;
    benchmark::DoNotOptimize(viewer.frame().pixels.data());
  }
  state.counters["build_ms"] = viewer.last_build_ms();
  state.counters["frame_ms"] = viewer.last_frame_ms();
  state.counters["groups"] = static_cast<double>(viewer.last_build_stats().groups);
  state.counters["rebuilt"] = static_cast<double>(viewer.last_build_stats().rebuilt);
}

// What the cache adds to a rebuild: grouping the walls and joining the groups' meshes, all
// reused (a plan that did not change).
void BM_ModelCacheReuse(benchmark::State& state, const std::string& name) {
  const Plan plan = open_viewer(name).session().plan();
  ModelCache cache;
  (void)cache.build(plan, {});
  for (auto _ : state) benchmark::DoNotOptimize(cache.build(plan, {}).walls.n_faces());
  state.counters["groups"] = static_cast<double>(cache.last_stats().groups);
  state.counters["rebuilt"] = static_cast<double>(cache.last_stats().rebuilt);
}

BENCHMARK_CAPTURE(BM_ViewOrbitFrame, studio, std::string("studio"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewOrbitFrame, flat, std::string("flat"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewOrbitFrame, office, std::string("office"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewOrbitFrame, house, std::string("house"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewEditFrame, studio, std::string("studio"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewEditFrame, house, std::string("house"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewEditFrame, sample, std::string("sweethome3d/Sample"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewEditFrame, four_bedroom, std::string("sweethome3d/4-BedroomHouse"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelCacheReuse, four_bedroom, std::string("sweethome3d/4-BedroomHouse"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelCacheReuse, sample, std::string("sweethome3d/Sample"))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
