// SPDX-License-Identifier: GPL-3.0-or-later
// Shadow-map pass (depth seen from the light) and the biased hard/PCF lookup.
#include "render/shadow_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>
#include <glm/gtc/matrix_transform.hpp>

#include "render/detail/shadow_pass.h"
#include "render/detail/wide_loops.h"
#include "render/shading.h"

namespace roomcad {
namespace {

/// The light's view and its extent around the scene: half sizes and the depth range, metres.
struct LightFrame {
  glm::dmat4 view{1.0};
  double half_x = 1.0, half_y = 1.0, near_d = 0.0, far_d = 1.0;
};

/// The light's frame around `casters` (across) and `scene` (in depth), both in the scene's
/// frame: the map covers what casts shadows, its depth range everything that may receive them.
LightFrame fit_light_frame(const Box3& casters, const Box3& scene, const glm::dvec3& to_light) {
  const glm::dvec3 center = (low_corner(casters) + high_corner(casters)) / 2.0;
  const double radius = glm::length(high_corner(scene) - low_corner(scene)) / 2.0 +
                        glm::length(center - (low_corner(scene) + high_corner(scene)) / 2.0) + 1.0;
  const glm::dvec3 up = std::abs(to_light.z) < 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  LightFrame f;
  f.view = glm::lookAtRH(center + to_light * radius, center, up);
  double lo = 1e300, hi = -1e300, hx = 0.0, hy = 0.0;
  for (int i = 0; i < 8; ++i) {
    const auto corner = [i](const Box3& b) {
      return glm::dvec4((i & 1) ? b.high[0] : b.low[0], (i & 2) ? b.high[1] : b.low[1],
                        (i & 4) ? b.high[2] : b.low[2], 1.0);
    };
    const glm::dvec4 v = f.view * corner(casters);
    hx = std::max(hx, std::abs(v.x));
    hy = std::max(hy, std::abs(v.y));
    const double d = -(f.view * corner(scene)).z;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  f.half_x = hx * 1.001 + 1e-3;  // a sliver of margin keeps the bounds' faces inside
  f.half_y = hy * 1.001 + 1e-3;
  f.near_d = lo - 0.01;
  f.far_d = hi + 0.01;
  return f;
}

glm::dmat4 light_projection(const LightFrame& f) {
  glm::dmat4 p(0.0);
  p[0][0] = 1.0 / f.half_x;
  p[1][1] = 1.0 / f.half_y;
  p[2][2] = 1.0 / (f.far_d - f.near_d);
  p[3][2] = f.far_d / (f.far_d - f.near_d);
  p[3][3] = 1.0;
  return p;
}

void rasterize_map(const Scene& scene, int resolution, ShadowMap& map,
                   detail::BinnedTriangles& bins) {
  detail::run_geometry_pass(
      scene,
      detail::GeometryPass{.uniform_view_projection = map.light_view_projection,
                           .width = resolution,
                           .height = resolution,
                           .tile_size = 128,
                           .cull_back_faces = true,
                           .pass = kShadowPass,
                           .uniform_viewer = glm::vec4(map.to_light, 0.f)},
      bins);
  tbb::parallel_for(0, bins.tile_count(), [&](int tile) {
    RasterTarget target = detail::tile_rectangle(bins, tile);  // tiles write disjoint texels
    target.depth = &map.depth.at(target.x0 + kShadowBorder, target.y0 + kShadowBorder);
    target.stride = map.depth.width;
    detail::rasterize_tile(bins, tile, target);
  });
}

}  // namespace

void detail::render_shadow_map_into(const Scene& scene, const Light& light, int resolution,
                                    ShadowMap& map, BinnedTriangles& bins) {
  resolution = std::max(resolution, 1);
  const int side = resolution + 2 * kShadowBorder;
  std::vector<float> depth = std::move(map.depth.values);  // keeps its memory
  depth.assign(static_cast<std::size_t>(side) * side, -std::numeric_limits<float>::infinity());
  map = ShadowMap{};
  map.resolution = resolution;
  map.depth.width = map.depth.height = side;
  map.depth.values = std::move(depth);
  for (int y = 0; y < resolution; ++y) {  // the map itself: nothing there yet
    float* row = &map.depth.at(kShadowBorder, y + kShadowBorder);
    std::fill_n(row, resolution, 0.f);
  }
  map.to_light = to_shading_light(light).to_light;
  const glm::dvec3 to_light(map.to_light);
  if (is_empty(scene.bounds)) return;
  Box3 local = scene.bounds;  // the map looks at the scene's corners, in the scene's frame
  for (int k = 0; k < 3; ++k) {
    local.low[std::size_t(k)] -= scene.origin[k];
    local.high[std::size_t(k)] -= scene.origin[k];
  }
  // the map covers what casts shadows: the scene's bounds when everything does, so that a
  // scene of the model alone keeps its map to the bit
  const Box3 casters = pass_bounds(scene, kShadowPass).value_or(local);
  if (is_empty(casters)) return;
  const LightFrame frame = fit_light_frame(casters, local, to_light);
  map.light_view_projection = glm::mat4(light_projection(frame) * frame.view);
  map.light_rotation = glm::mat3(glm::dmat3(frame.view));
  map.texel_x = static_cast<float>(2.0 * frame.half_x / resolution);
  map.texel_y = static_cast<float>(2.0 * frame.half_y / resolution);
  map.depth_range = static_cast<float>(frame.far_d - frame.near_d);
  rasterize_map(scene, resolution, map, bins);
}

ShadowMap render_shadow_map(const Scene& scene, const Light& light, int resolution) {
  ShadowMap map;
  detail::BinnedTriangles bins;
  detail::render_shadow_map_into(scene, light, resolution, map, bins);
  return map;
}

ShadowReceiver shadow_receiver(const ShadowMap& map, const glm::vec3& normal,
                               const std::array<glm::vec3, 3>& corners) {
  ShadowReceiver r;
  const glm::vec3 n = map.light_rotation * normal;  // light view: +z towards the light
  r.faces_light = n.z > 0.f;
  if (!r.faces_light || map.texel_x == 0.f) return r;
  const float cos_t = std::max(n.z, 0.1f);  // caps tan(angle) at about 10
  const float tan_t = std::sqrt(1.f - cos_t * cos_t) / cos_t;
  r.grad_u = -n.x * map.texel_x / (cos_t * map.depth_range);
  r.grad_v = n.y * map.texel_y / (cos_t * map.depth_range);
  r.bias = map.texel_size() * (0.05f + 0.1f * tan_t) / map.depth_range;
  std::array<glm::vec3, 3> texel;
  const float size = static_cast<float>(map.resolution);
  for (int c = 0; c < 3; ++c) {
    const glm::vec4 p = map.light_view_projection * glm::vec4(corners[c], 1.f);
    texel[c] = {(p.x + 1.f) * 0.5f * size, (1.f - p.y) * 0.5f * size, p.z};
  }
  r.corner0 = texel[0];
  r.to_corner1 = texel[1] - texel[0];
  r.to_corner2 = texel[2] - texel[0];
  return r;
}

namespace {

/// floor(x) for map coordinates (|x| < 2^31), inline and branch-free: std::floor is a
/// library call on SSE2, and the loops calling this vectorise.
int floor_to_int(float x) {
  const int i = static_cast<int>(x);
  return i - (static_cast<float>(i) > x);
}

/// Samples whose map positions shadow_amounts computes at once.
constexpr int kMaxShadowBatch = 64;
template <typename T>
using Batch = std::array<T, kMaxShadowBatch>;

}  // namespace

ROOMCAD_WIDE_LOOPS void shadow_amounts(const ShadowMap& map, const ShadowReceiver& receiver,
                                       ShadowFilter filter, const float* w1, const float* w2,
                                       int count, float* out) {
  const bool lit = filter == ShadowFilter::off || map.texel_x == 0.f;
  if (lit || !receiver.faces_light) {
    std::fill(out, out + count, lit ? 0.f : 1.f);
    return;
  }
  // Hard: whether the texel under map point (u, v) occludes the receiver's biased plane
  // through depth z there. PCF: the same test for the four texels around the point, weighted
  // bilinearly (as graphics hardware filters shadow maps), so the penumbra is one texel wide
  // and changes smoothly. Points are clamped to one texel outside the map, where every texel
  // read lies in its frame (which never occludes), so no lookup tests bounds.
  const bool pcf = filter == ShadowFilter::pcf;
  const float offset = pcf ? 0.5f : 0.f;
  const float lo = -1.f, hi = static_cast<float>(map.resolution) + 1.f;
  const int stride = map.depth.width;
  const float* texels = map.depth.values.data() + kShadowBorder * stride + kShadowBorder;  // (0, 0)
  const glm::vec3 c0 = receiver.corner0, e1 = receiver.to_corner1, e2 = receiver.to_corner2;
  const float grad_u = receiver.grad_u, grad_v = receiver.grad_v;
  Batch<int> index;
  Batch<float> fu, fv, d00;
  std::array<Batch<float>, 4> t;  // texels (iu, iv), (iu + 1, iv), (iu, iv + 1), (iu + 1, iv + 1)
  for (int first = 0; first < count; first += kMaxShadowBatch) {
    const int n = std::min(count - first, kMaxShadowBatch);
    for (int i = 0; i < n; ++i) {  // branch-free: vectorised
      const float a = w1[first + i], b = w2[first + i];
      const float u = std::clamp(c0.x + a * e1.x + b * e2.x, lo, hi);
      const float v = std::clamp(c0.y + a * e1.y + b * e2.y, lo, hi);
      const float z = c0.z + a * e1.z + b * e2.z;
      const int iu = floor_to_int(u - offset), iv = floor_to_int(v - offset);
      fu[i] = u - offset - static_cast<float>(iu);
      fv[i] = v - offset - static_cast<float>(iv);
      index[i] = iv * stride + iu;
      // the receiver's plane extended to the centre of texel (iu, iv)
      d00[i] = z + grad_u * (iu + 0.5f - u) + grad_v * (iv + 0.5f - v) + receiver.bias;
    }
    float* amount = out + first;
    if (!pcf) {
      for (int i = 0; i < n; ++i) t[0][i] = texels[index[i]];  // a gather: loads alone
      for (int i = 0; i < n; ++i) amount[i] = t[0][i] > d00[i] ? 1.f : 0.f;
      continue;
    }
    for (int i = 0; i < n; ++i) {  // a gather: loads alone
      const float* texel = texels + index[i];
      t[0][i] = texel[0];
      t[1][i] = texel[1];
      t[2][i] = texel[stride];
      t[3][i] = texel[stride + 1];
    }
    for (int i = 0; i < n; ++i) {  // vectorised
      const float d10 = d00[i] + grad_u, d01 = d00[i] + grad_v, d11 = d01 + grad_u;
      const float s0 = t[0][i] > d00[i] ? 1.f : 0.f, s1 = t[1][i] > d10 ? 1.f : 0.f;
      const float s2 = t[2][i] > d01 ? 1.f : 0.f, s3 = t[3][i] > d11 ? 1.f : 0.f;
      amount[i] = (1.f - fv[i]) * ((1.f - fu[i]) * s0 + fu[i] * s1) +
                  fv[i] * ((1.f - fu[i]) * s2 + fu[i] * s3);
    }
  }
}

}  // namespace roomcad
