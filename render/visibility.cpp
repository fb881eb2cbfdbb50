// Seed 004's pre-pass: set-up (back-face cull, projection to the sample grid), then the split.
#include "render/visibility.h"

#include <atomic>
#include <cmath>

#include "render/detail/visibility_split.h"
#include "render/shadow_map.h"

namespace roomcad {
namespace {

/// Near-plane crossings: a vertex with clip w below this is treated as crossing.
constexpr double kMinW = 1e-6;

bool is_front_facing(const Scene& scene, std::size_t t, const CameraMatrices& cam) {
  if (scene.two_sided[t]) return true;
  const glm::dvec3 n(scene.normals[t]);
  const glm::dvec3 corner(scene.corners[3 * t]);
  const glm::dvec3 to_eye = cam.orthographic ? -cam.forward : cam.eye - corner;
  // Nearly edge-on faces cover (almost) no samples, but keep them: the rasteriser decides
  // their facing in fixed point.
  return glm::dot(n, to_eye) > -1e-6 * glm::length(to_eye);
}

enum class Projected { flat, behind, across_eye_plane, no_area };

/// Projects a triangle to the sample grid (a corner between the eye and the near plane still
/// projects; the rasteriser clips it, so the projection is larger: conservative).
Projected flatten(const Scene& scene, std::size_t t, const VisibilityView& v,
                  detail::FlatTriangle& out) {
  glm::dvec3 q[3];
  int behind = 0;
  for (int c = 0; c < 3; ++c) {
    const glm::dvec3 corner(scene.corners[3 * t + c]);
    const glm::dvec4 clip = v.camera.view_projection * glm::dvec4(corner, 1.0);
    if (!(clip.w > kMinW)) {
      ++behind;
      continue;
    }
    q[c] = {(clip.x / clip.w + 1.0) * 0.5 * v.width, (1.0 - clip.y / clip.w) * 0.5 * v.height,
            clip.z / clip.w};
    out.p[c] = {q[c].x, q[c].y};
    out.box.add(out.p[c]);
  }
  if (behind == 3) return Projected::behind;
  if (behind > 0) return Projected::across_eye_plane;
  const glm::dvec3 e1 = q[1] - q[0], e2 = q[2] - q[0];
  const double det = e1.x * e2.y - e1.y * e2.x;
  if (det == 0.0) return Projected::no_area;
  // depth = z0 + a (x - x0) + b (y - y0), solved from the other two corners
  const double a = (e1.z * e2.y - e2.z * e1.y) / det;
  const double b = (e2.z * e1.x - e1.z * e2.x) / det;
  out.depth = {a, b, q[0].z - a * q[0].x - b * q[0].y};
  out.id = static_cast<std::uint32_t>(t);
  return Projected::flat;
}

}  // namespace

VisibilityResult find_visible_faces(const Scene& scene, const VisibilityView& view) {
  VisibilityResult result;
  const std::size_t n = scene.triangle_count();
  std::vector<std::atomic<std::uint8_t>> visible(n);
  std::vector<detail::FlatTriangle> flat;
  for (std::size_t t = 0; t < n; ++t) {
    if (!is_front_facing(scene, t, view.camera)) continue;
    ++result.front_facing;
    detail::FlatTriangle f;
    const Projected p = flatten(scene, t, view, f);
    if (p == Projected::flat) {
      flat.push_back(f);
    } else if (p == Projected::across_eye_plane) {  // kept, conservatively, and hides nothing
      ++result.near_clipped;
      visible[t].store(1, std::memory_order_relaxed);
    }
  }
  detail::SplitCounters counters;
  detail::group_coplanar(flat);
  detail::split_picture(flat, view.width, view.height, visible, counters);
  result.visible.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    result.visible[t] = visible[t].load(std::memory_order_relaxed);
    result.visible_count += result.visible[t];
  }
  result.regions = counters.regions;
  result.crossings = counters.crossings;
  return result;
}

VisibilityResult find_lit_faces(const Scene& scene, const Light& light, int resolution) {
  // The shadow map's own frame, so both agree on what the light sees; one texel is enough to
  // get its matrices.
  const ShadowMap frame = render_shadow_map(scene, light, 1);
  VisibilityView view;
  view.width = view.height = resolution;
  view.camera.view_projection = glm::dmat4(frame.light_view_projection);
  view.camera.forward = -glm::dvec3(frame.to_light);
  view.camera.orthographic = true;
  return find_visible_faces(scene, view);
}

}  // namespace roomcad
