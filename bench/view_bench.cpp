// Window frame times: the viewer (view/viewer.h) at 1280 x 720 on every bundled example, with
// the overlay, as the window draws them while orbiting (each frame a new camera). A frame of
// an edit adds the model rebuild: BM_ViewEditFrame moves a wall one cell and back.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <stdexcept>
#include <string>

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
}

BENCHMARK_CAPTURE(BM_ViewOrbitFrame, studio, std::string("studio"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewOrbitFrame, flat, std::string("flat"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewOrbitFrame, office, std::string("office"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewOrbitFrame, house, std::string("house"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewEditFrame, studio, std::string("studio"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ViewEditFrame, house, std::string("house"))->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
