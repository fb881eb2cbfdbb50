// Shadow-map pass (depth seen from the light) and the biased hard/PCF lookup.
#include "render/shadow_map.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <tbb/parallel_for.h>

#include "render/detail/shadow_pass.h"
#include "render/shading.h"

namespace roomcad {
namespace {

/// The light's view and its extent around the scene: half sizes and the depth range, metres.
struct LightFrame {
  glm::dmat4 view{1.0};
  double half_x = 1.0, half_y = 1.0, near_d = 0.0, far_d = 1.0;
};

LightFrame fit_light_frame(const Bounds& scene, const glm::dvec3& to_light) {
  const glm::dvec3 center = (scene.min + scene.max) / 2.0;
  const double radius = glm::length(scene.max - scene.min) / 2.0 + 1.0;
  const glm::dvec3 up = std::abs(to_light.z) < 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  LightFrame f;
  f.view = glm::lookAtRH(center + to_light * radius, center, up);
  double lo = 1e300, hi = -1e300, hx = 0.0, hy = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 c((i & 1) ? scene.max.x : scene.min.x, (i & 2) ? scene.max.y : scene.min.y,
                       (i & 4) ? scene.max.z : scene.min.z);
    const glm::dvec4 v = f.view * glm::dvec4(c, 1.0);
    hx = std::max(hx, std::abs(v.x));
    hy = std::max(hy, std::abs(v.y));
    lo = std::min(lo, -v.z);
    hi = std::max(hi, -v.z);
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
      scene, detail::GeometryPass{.uniform_view_projection = map.light_view_projection,
                                  .width = resolution,
                                  .height = resolution,
                                  .tile_size = 128,
                                  .cull_back_faces = true,
                                  .uniform_viewer = glm::vec4(map.to_light, 0.f)},
      bins);
  tbb::parallel_for(0, bins.tile_count(), [&](int tile) {
    RasterTarget target = detail::tile_rectangle(bins, tile);  // tiles write disjoint texels
    target.depth = &map.depth.at(target.x0, target.y0);
    target.stride = resolution;
    detail::rasterize_tile(bins, tile, target);
  });
}

}  // namespace

void detail::render_shadow_map_into(const Scene& scene, const Light& light, int resolution,
                                    ShadowMap& map, BinnedTriangles& bins) {
  resolution = std::max(resolution, 1);
  std::vector<float> depth = std::move(map.depth.values);  // keeps its memory
  depth.assign(static_cast<std::size_t>(resolution) * resolution, 0.f);
  map = ShadowMap{};
  map.depth.width = map.depth.height = resolution;
  map.depth.values = std::move(depth);
  map.to_light = to_shading_light(light).to_light;
  const glm::dvec3 to_light(map.to_light);
  if (scene.bounds.is_empty()) return;
  Bounds local = scene.bounds;  // the map looks at the scene's corners, in the scene's frame
  local.min -= scene.origin;
  local.max -= scene.origin;
  const LightFrame frame = fit_light_frame(local, to_light);
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
  const float cos_t = std::max(n.z, 0.1f);          // caps tan(angle) at about 10
  const float tan_t = std::sqrt(1.f - cos_t * cos_t) / cos_t;
  r.grad_u = -n.x * map.texel_x / (cos_t * map.depth_range);
  r.grad_v = n.y * map.texel_y / (cos_t * map.depth_range);
  r.bias = map.texel_size() * (0.05f + 0.1f * tan_t) / map.depth_range;
  std::array<glm::vec3, 3> texel;
  const float size = static_cast<float>(map.depth.width);
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

/// floor(x) for map coordinates (|x| < 2^31), inline: std::floor is a library call on SSE2.
int floor_to_int(float x) {
  const int i = static_cast<int>(x);
  return i - (static_cast<float>(i) > x);
}

/// Samples whose map positions shadow_amounts computes at once.
constexpr int kMaxShadowBatch = 64;

/// 1 if texel (iu, iv) lies nearer the light than `depth`, else 0 (also outside the map: lit).
float is_occluded(const ShadowMap& map, int iu, int iv, float depth) {
  const auto size = static_cast<unsigned>(map.depth.width);
  if (static_cast<unsigned>(iu) >= size || static_cast<unsigned>(iv) >= size) return 0.f;
  return map.depth.values[static_cast<std::size_t>(iv) * size + iu] > depth ? 1.f : 0.f;
}

/// Hard: whether the texel under map point (u, v) occludes the receiver's biased plane
/// through depth z there. PCF: the same test for the four texels around the point, weighted
/// bilinearly (as graphics hardware filters shadow maps), so the penumbra is one texel wide
/// and changes smoothly.
float filtered_lookup(const ShadowMap& map, const ShadowReceiver& r, float u, float v, float z,
                      ShadowFilter filter) {
  // The receiver's biased depth at the centre of texel (iu, iv).
  const auto depth_at = [&](int iu, int iv) {
    return z + r.grad_u * (iu + 0.5f - u) + r.grad_v * (iv + 0.5f - v) + r.bias;
  };
  if (filter == ShadowFilter::hard) {
    const int iu = floor_to_int(u), iv = floor_to_int(v);
    return is_occluded(map, iu, iv, depth_at(iu, iv));
  }
  const int iu = floor_to_int(u - 0.5f), iv = floor_to_int(v - 0.5f);
  const float fu = u - 0.5f - static_cast<float>(iu), fv = v - 0.5f - static_cast<float>(iv);
  const float d00 = depth_at(iu, iv), d10 = d00 + r.grad_u, d01 = d00 + r.grad_v;
  const float d11 = d01 + r.grad_u;
  const auto size = static_cast<unsigned>(map.depth.width);
  std::array<float, 4> s;  // occluded: (iu, iv), (iu + 1, iv), (iu, iv + 1), (iu + 1, iv + 1)
  if (static_cast<unsigned>(iu) < size - 1u && static_cast<unsigned>(iv) < size - 1u) {
    const float* row = &map.depth.values[static_cast<std::size_t>(iv) * size + iu];  // all in
    s = {row[0] > d00 ? 1.f : 0.f, row[1] > d10 ? 1.f : 0.f, row[size] > d01 ? 1.f : 0.f,
         row[size + 1] > d11 ? 1.f : 0.f};
  } else {
    s = {is_occluded(map, iu, iv, d00), is_occluded(map, iu + 1, iv, d10),
         is_occluded(map, iu, iv + 1, d01), is_occluded(map, iu + 1, iv + 1, d11)};
  }
  return (1.f - fv) * ((1.f - fu) * s[0] + fu * s[1]) + fv * ((1.f - fu) * s[2] + fu * s[3]);
}

}  // namespace

void shadow_amounts(const ShadowMap& map, const ShadowReceiver& receiver, ShadowFilter filter,
                    const float* w1, const float* w2, int count, float* out) {
  const bool lit = filter == ShadowFilter::off || map.texel_x == 0.f;
  if (lit || !receiver.faces_light) {
    std::fill(out, out + count, lit ? 0.f : 1.f);
    return;
  }
  // The outside of the map is lit, so coordinates far outside it (up to the float -> int
  // limit) must stay finite: clamp them to just outside.
  const float limit = static_cast<float>(map.depth.width) + 2.f;
  const glm::vec3 c0 = receiver.corner0, e1 = receiver.to_corner1, e2 = receiver.to_corner2;
  std::array<float, kMaxShadowBatch> u, v, z;
  for (int first = 0; first < count; first += kMaxShadowBatch) {
    const int n = std::min(count - first, kMaxShadowBatch);
    for (int i = 0; i < n; ++i) {  // branch-free: vectorised
      const float a = w1[first + i], b = w2[first + i];
      u[i] = std::clamp(c0.x + a * e1.x + b * e2.x, -2.f, limit);
      v[i] = std::clamp(c0.y + a * e1.y + b * e2.y, -2.f, limit);
      z[i] = c0.z + a * e1.z + b * e2.z;
    }
    for (int i = 0; i < n; ++i) {
      out[first + i] = filtered_lookup(map, receiver, u[i], v[i], z[i], filter);
    }
  }
}

}  // namespace roomcad
