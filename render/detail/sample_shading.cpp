// SPDX-License-Identifier: GPL-3.0-or-later
// The fragment stage: per triangle set-up once, then arrays of samples through interpolation,
// shadow lookups and shading.
#include "render/detail/sample_shading.h"

#include <algorithm>
#include <array>

#include "render/detail/wide_loops.h"

namespace roomcad::detail {
namespace {

/// What one visible triangle gives each of its samples (its `varying_` set-up), loaded once
/// per run of samples that show it.
struct TriangleVarying {
  std::uint32_t id = kNoTriangle;
  std::array<glm::vec3, 3> corners{};
  glm::vec3 color{0.f};  ///< the face's plain colour
  bool is_floor = false;
  BarycentricPlanes weights;
  SurfaceLighting lighting;
  std::array<ShadowReceiver, kMaxLights> receivers{};
};

void load_triangle(const ShadeUniforms& u, std::uint32_t id, TriangleVarying& v) {
  const Scene& scene = *u.scene;
  v.id = id;
  const ScreenTriangle& screen = u.bins->at(id);
  const std::size_t tri = screen.triangle;
  for (int c = 0; c < 3; ++c) v.corners[c] = scene.corners[3 * tri + c];
  // n . (eye - p) is the same at every point p of the triangle's plane, so one test per
  // triangle turns the back of a two-sided face towards the viewer.
  const glm::vec3 normal = scene.normals[tri];
  const glm::vec3 to_eye =
      u.shading.orthographic ? -u.shading.forward : u.shading.eye - v.corners[0];
  const glm::vec3 facing = glm::dot(normal, to_eye) < 0.f ? -normal : normal;
  v.color = to_unit_rgb(scene.colors[tri]);
  v.is_floor = scene.kinds[tri] == FaceKind::floor;
  v.weights = barycentric_planes(screen);
  v.lighting = light_surface(u.shading, facing, v.corners);
  for (std::size_t k = 0; k < u.shadow_maps->size(); ++k) {
    v.receivers[k] = shadow_receiver((*u.shadow_maps)[k], facing, v.corners);
  }
}

/// Fills the run's samples x0, x0 + 1, ... of row y (pixel centres) from the triangle.
void interpolate_run(const ShadeUniforms& u, const TriangleVarying& v, int x0, int y,
                     SampleRun& run) {
  const glm::dvec3 d = v.weights.denominator, a = v.weights.weight1, b = v.weights.weight2;
  const double py = y + 0.5;
  const double d_row = d.y * py + d.z, a_row = a.y * py + a.z, b_row = b.y * py + b.z;
  const glm::vec3 e1 = v.corners[1] - v.corners[0], e2 = v.corners[2] - v.corners[0];
  for (int i = 0; i < run.count; ++i) {  // branch-free: vectorised
    const double px = x0 + i + 0.5;
    // Perspective-correct: one division, in float (twice as many lanes as double): the
    // planes stay in double, where their sums cancel; the quotients are floats either way.
    const float inv = 1.f / static_cast<float>(d.x * px + d_row);
    run.w1[i] = static_cast<float>(a.x * px + a_row) * inv;
    run.w2[i] = static_cast<float>(b.x * px + b_row) * inv;
    const glm::vec3 world = v.corners[0] + run.w1[i] * e1 + run.w2[i] * e2;
    run.x[i] = world.x;
    run.y[i] = world.y;
    run.z[i] = world.z;
  }
  run.color = v.color;
  if (v.is_floor) {
    mark_grid_lines(u.shading.grid, run);
  } else {
    std::fill_n(run.tint.begin(), run.count, 1.f);
  }
  for (std::size_t k = 0; k < u.shadow_maps->size(); ++k) {
    shadow_amounts((*u.shadow_maps)[k], v.receivers[k], u.filter, run.w1.data(), run.w2.data(),
                   run.count, run.shadow[k].data());
  }
}

/// Recently loaded triangles, by the low bits of their ids: rows cross the same few triangles
/// again and again (the two halves of a floor tile alternate on every row), and a load costs
/// as much as shading a dozen samples.
class TriangleCache {
 public:
  const TriangleVarying& get(const ShadeUniforms& u, std::uint32_t id) {
    TriangleVarying& slot = slots_[id % kSlots];
    if (slot.id != id) load_triangle(u, id, slot);
    return slot;
  }

 private:
  static constexpr std::uint32_t kSlots = 16;
  std::array<TriangleVarying, kSlots> slots_{};
};

/// The end of the run of samples from `i` that show the triangle sample i shows, at most
/// `limit`: eight samples a step while all eight match (their compares vectorise, one branch
/// for eight), then one by one.
int run_end(const std::uint32_t* ids, int i, int limit) {
  constexpr int kStep = 8;
  const std::uint32_t id = ids[i];
  int end = i + 1;
  for (; end + kStep <= limit; end += kStep) {
    std::uint32_t differ = 0;
    for (int k = 0; k < kStep; ++k) differ |= ids[end + k] ^ id;
    if (differ != 0) break;
  }
  while (end < limit && ids[end] == id) ++end;
  return end;
}

}  // namespace

ROOMCAD_WIDE_LOOPS void shade_tile(const ShadeUniforms& u, const RasterTarget& t, glm::vec3* rgb) {
  const int w = t.x1 - t.x0;
  TriangleCache cache;
  SampleRun run;
  for (int y = t.y0; y < t.y1; ++y) {
    // a local: the stores below cannot change it
    const glm::vec3 background =
        u.sky_bottom ? glm::mix(u.background, *u.sky_bottom, (y + 0.5f) / u.sky_rows)
                     : u.background;
    const std::uint32_t* ids = t.ids + static_cast<std::ptrdiff_t>(y - t.y0) * w;
    glm::vec3* out = rgb + static_cast<std::ptrdiff_t>(y - t.y0) * w;
    for (int i = 0; i < w;) {
      const int end = run_end(ids, i, std::min(w, i + kMaxRunSamples));
      if (ids[i] == kNoTriangle) {
        std::fill(out + i, out + end, background);
      } else {
        const TriangleVarying& v = cache.get(u, ids[i]);
        run.count = end - i;
        interpolate_run(u, v, t.x0 + i, y, run);
        shade_run(u.shading, v.lighting, run, out + i);
      }
      i = end;
    }
  }
}

}  // namespace roomcad::detail
