// SPDX-License-Identifier: GPL-3.0-or-later
// Makarov & Safin's pre-pass: the rasteriser's own set-up (clip, fixed point, back faces), then the
// split.
#include "render/visibility.h"

#include <algorithm>
#include <atomic>

#include "render/detail/geometry_pass.h"
#include "render/detail/visibility_split.h"
#include "render/shadow_map.h"

namespace roomcad {
namespace {

/// A screen triangle on the sample grid: corners from its fixed point, the depth plane through
/// its corner depths (orders faces along contours; samples are decided by `screen` itself).
detail::FlatTriangle flatten(const ScreenTriangle& s) {
  detail::FlatTriangle out;
  out.screen = s;
  out.id = s.triangle;
  glm::dvec3 q[3];
  for (int c = 0; c < 3; ++c) {
    q[c] = {static_cast<double>(s.x[c]) / kSubpixelScale,
            static_cast<double>(s.y[c]) / kSubpixelScale, static_cast<double>(s.depth[c])};
    out.p[c] = {q[c].x, q[c].y};
    add_point(out.box, out.p[c].x, out.p[c].y);
  }
  // depth = z0 + a (x - x0) + b (y - y0), solved from the other two corners (set-up rejects
  // triangles of zero area, so det != 0)
  const glm::dvec3 e1 = q[1] - q[0], e2 = q[2] - q[0];
  const double det = e1.x * e2.y - e1.y * e2.x;
  const double a = (e1.z * e2.y - e2.z * e1.y) / det;
  const double b = (e2.z * e1.x - e1.z * e2.x) / det;
  out.depth = {a, b, q[0].z - a * q[0].x - b * q[0].y};
  return out;
}

/// The rasteriser's own set-up (transform, clip, fixed point, back faces), so that the
/// pre-pass sees exactly the triangles the z-buffer draws. @return them in its draw order.
std::vector<detail::FlatTriangle> set_up(const Scene& scene, const VisibilityView& view) {
  detail::BinnedTriangles bins;
  detail::run_geometry_pass(scene,
                            {.uniform_view_projection = glm::mat4(view.camera.view_projection),
                             .width = view.width,
                             .height = view.height,
                             .tile_size = view.tile_size,
                             .cull_back_faces = true,
                             .uniform_clusters = view.clusters,
                             .uniform_views = view.views},
                            bins);
  std::vector<detail::FlatTriangle> flat;
  for (const auto& chunk : bins.chunks)
    for (const ScreenTriangle& s : chunk) flat.push_back(flatten(s));
  return flat;  // chunk by chunk is the order the rasteriser draws in
}

}  // namespace

VisibilityResult find_visible_faces(const Scene& scene, const VisibilityView& view) {
  VisibilityResult result;
  const std::size_t n = scene.triangle_count();
  std::vector<std::atomic<std::uint8_t>> visible(n);
  std::vector<detail::FlatTriangle> flat = set_up(scene, view);
  std::vector<std::uint8_t> drawn(n, 0);  // a clipped triangle may give several
  for (const detail::FlatTriangle& f : flat) drawn[f.id] = 1;
  result.front_facing = static_cast<std::size_t>(std::count(drawn.begin(), drawn.end(), 1));
  detail::SplitCounters counters;
  detail::group_coplanar(flat);
  detail::split_picture(flat, {view.width, view.height, view.tile_size}, visible, counters);
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
