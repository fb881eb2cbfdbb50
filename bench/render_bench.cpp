// SPDX-License-Identifier: GPL-3.0-or-later
// Render benchmarks: frame times at 1920 x 1080 for grids of rooms from ~1k to ~2M triangles,
// without shadows, with PCF and with hard shadows, at 1 and 2 threads; and shadow-map
// resolution against shadow error (vs ray-traced shadows) and time. The scene is flattened
// once (as a GPU uploads its mesh once), so a frame is what render_scene does.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>

#include "bench/room_grid.h"
#include "render/renderer.h"

namespace roomcad {
namespace {

const Scene& grid_scene(int n) {
  static std::map<int, std::unique_ptr<Scene>> cache;
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<Scene>(flatten_model(samples::make_room_grid(n)));
  return *slot;
}

/// What `roomcad render` fills without --depth and --ids.
constexpr FrameOutputs kColourOnly{.depth = false, .object_ids = false};

/// Args: rooms per side, shadows (0 off, 1 pcf, 2 hard), threads.
void BM_Frame1080p(benchmark::State& state) {
  const Scene& scene = grid_scene(static_cast<int>(state.range(0)));
  constexpr ShadowFilter filters[] = {ShadowFilter::off, ShadowFilter::pcf, ShadowFilter::hard};
  const RenderOptions options{.width = 1920,
                              .height = 1080,
                              .shadows = filters[state.range(1)],
                              .threads = static_cast<int>(state.range(2)),
                              .outputs = kColourOnly};
  FrameBuffers out;
  RenderStats stats, sum;
  for (auto _ : state) {
    render_scene(scene, options, out, &stats);
    sum.shadow_ms += stats.shadow_ms;
    sum.raster_ms += stats.raster_ms;
  }
  const double frames = static_cast<double>(state.iterations());
  state.counters["triangles"] = static_cast<double>(scene.triangle_count());
  state.counters["shadow_ms"] = sum.shadow_ms / frames;
  state.counters["raster_ms"] = sum.raster_ms / frames;
}
BENCHMARK(BM_Frame1080p)
    ->ArgsProduct({{2, 10, 25, 50, 82}, {0, 1, 2}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.3);

/// The 3 x 3 grid from the default camera at 400 x 300, Phong, PCF shadows.
RenderOptions aa_options(int scale, int ssaa) {
  return RenderOptions{.width = 400 * scale, .height = 300 * scale, .ssaa = ssaa};
}

/// The reference for anti-aliasing: 1600 x 1200 at ssaa 4, box-filtered to 400 x 300 (64
/// samples a pixel, where ssaa 4 has 16).
const RgbImage& aa_reference(const Scene& scene) {
  static RgbImage reference;
  if (!reference.pixels.empty()) return reference;
  FrameBuffers big;
  render_scene(scene, aa_options(4, 4), big);
  reference = RgbImage(400, 300);
  for (int y = 0; y < 300; ++y)
    for (int x = 0; x < 400; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int k = 0; k < 16; ++k) sum += big.color.at(4 * x + k % 4, 4 * y + k / 4)[c];
        reference.at(x, y)[c] = static_cast<std::uint8_t>((sum + 8) / 16);
      }
  return reference;
}

/// Arg: ssaa (samples per pixel side). Counters: mean absolute difference from the reference
/// (0-255 levels, all pixels and channels), share of pixels off by more than 8 levels in some
/// channel (edges), and the frame time.
void BM_AntiAliasingError(benchmark::State& state) {
  static const Scene scene = flatten_model(samples::make_room_grid(3));
  const RenderOptions options = aa_options(1, static_cast<int>(state.range(0)));
  FrameBuffers out;
  RenderStats stats;
  double frame_ms = 0.0;
  for (auto _ : state) {
    render_scene(scene, options, out, &stats);
    frame_ms += stats.frame_ms;
  }
  const RgbImage& ref = aa_reference(scene);
  double sum = 0.0, off = 0.0;
  for (std::size_t i = 0; i < ref.pixels.size(); i += 3) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int{ref.pixels[i + c]} - int{out.color.pixels[i + c]});
      sum += d;
      worst = std::max(worst, d);
    }
    off += worst > 8;
  }
  state.counters["mean_error_levels"] = sum / static_cast<double>(ref.pixels.size());
  state.counters["pixels_off_pct"] = 300.0 * off / static_cast<double>(ref.pixels.size());
  state.counters["frame_ms"] = frame_ms / static_cast<double>(state.iterations());
}
BENCHMARK(BM_AntiAliasingError)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// Shadowed floor pixels of a hard-shadow frame (unlit: a shadowed floor pixel is darker).
std::vector<int> shadow_classes(const FrameBuffers& out) {
  std::vector<int> classes(out.objects.ids.size(), -1);
  for (std::size_t i = 0; i < classes.size(); ++i) {
    if (out.objects.ids[i] == 0) classes[i] = out.color.pixels[3 * i] < test::kFloorColor.r / 2;
  }
  return classes;
}

/// The ray-traced shadow class of every floor pixel of the 3 x 3 grid seen from the top.
const std::vector<int>& reference_classes(const Model& m, const CameraMatrices& cam, int w, int h) {
  static std::vector<int> classes;
  if (!classes.empty()) return classes;
  const test::RayCaster all({&m.walls, &m.floor, &m.fixtures}), occluders({&m.walls, &m.fixtures});
  const glm::dvec3 to_light = -glm::normalize(glm::dvec3(-0.4, 0.5, -1.0));
  classes.assign(static_cast<std::size_t>(w) * h, -1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const test::PixelRay r = test::pixel_ray(cam, w, h, x, y);
      if (all.first_object(r.origin, r.direction) != 0) continue;
      const glm::dvec3 p = r.origin + r.direction * (-r.origin.z / r.direction.z);
      classes[static_cast<std::size_t>(y) * w + x] = occluders.is_blocked(p, to_light);
    }
  return classes;
}

/// Args: shadow-map resolution, filter (0 hard, 1 PCF). Counters: the share of floor pixels
/// whose shadow (darker than half the floor colour) differs from the ray-traced one, and the
/// shadow pass time.
void BM_ShadowResolutionError(benchmark::State& state) {
  static const Model model = samples::make_room_grid(3);
  const Scene scene = flatten_model(model);
  RenderOptions options{.width = 800,
                        .height = 800,
                        .shading = ShadingMode::unlit,
                        .shadows = state.range(1) ? ShadowFilter::pcf : ShadowFilter::hard,
                        .shadow_resolution = static_cast<int>(state.range(0))};
  options.camera = frame_view(scene.bounds, ViewPreset::top, Projection::orthographic, 50.0, 1.0);
  FrameBuffers out;
  RenderStats stats;
  double shadow_ms = 0.0;
  for (auto _ : state) {
    render_scene(scene, options, out, &stats);
    shadow_ms += stats.shadow_ms;
  }
  const auto& ref = reference_classes(model, frame_camera(scene, options), 800, 800);
  const std::vector<int> got = shadow_classes(out);
  double floor = 0, wrong = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (ref[i] < 0 || got[i] < 0) continue;
    ++floor;
    wrong += ref[i] != got[i];
  }
  state.counters["error_pct"] = 100.0 * wrong / floor;
  state.counters["texel_cm"] =
      100.0 * render_shadow_map(scene, default_light(), options.shadow_resolution).texel_size();
  state.counters["shadow_ms"] = shadow_ms / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ShadowResolutionError)
    ->ArgsProduct({{256, 512, 1024, 2048, 4096}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
