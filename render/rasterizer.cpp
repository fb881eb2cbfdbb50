// Edge-function rasterisation in fixed point, with the top-left rule and reversed-Z depth.
#include "render/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace roomcad {
namespace {

constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;

/// floor(a / b) for b > 0, also for negative a.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/// Twice the signed area of (a, b, p): the edge function of edge a -> b at p.
std::int64_t edge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                  std::int64_t px, std::int64_t py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/// One edge's function at the first pixel centre of the box, its steps, and the fill-rule
/// bias (0 for top and left edges, whose centres on the edge are drawn, else 1).
struct EdgeWalk {
  std::int64_t at_start = 0;
  std::int64_t step_x = 0;
  std::int64_t step_y = 0;
  std::int64_t bias = 0;
};

EdgeWalk walk_edge(const ScreenTriangle& t, int k, std::int64_t sx, std::int64_t sy) {
  const int a = (k + 1) % 3;
  const int b = (k + 2) % 3;
  const bool top_left = t.y[a] > t.y[b] || (t.y[a] == t.y[b] && t.x[b] > t.x[a]);
  EdgeWalk w;
  w.bias = top_left ? 0 : 1;
  w.at_start = edge(t.x[a], t.y[a], t.x[b], t.y[b], sx, sy) - w.bias;
  w.step_x = -static_cast<std::int64_t>(t.y[b] - t.y[a]) * kSubpixelScale;
  w.step_y = static_cast<std::int64_t>(t.x[b] - t.x[a]) * kSubpixelScale;
  return w;
}

}  // namespace

std::optional<ScreenTriangle> set_up_triangle(const std::array<ClipVertex, 3>& v, int width,
                                              int height, std::uint32_t triangle,
                                              Culling culling) {
  ScreenTriangle t;
  t.triangle = triangle;
  for (int i = 0; i < 3; ++i) {
    const glm::vec4& p = v[i].position;
    const float inv_w = 1.f / p.w;
    const double sx = (static_cast<double>(p.x) * inv_w + 1.0) * 0.5 * width;
    const double sy = (1.0 - static_cast<double>(p.y) * inv_w) * 0.5 * height;
    t.x[i] = static_cast<std::int32_t>(std::lround(sx * kSubpixelScale));
    t.y[i] = static_cast<std::int32_t>(std::lround(sy * kSubpixelScale));
    t.depth[i] = std::clamp(p.z * inv_w, 0.f, 1.f);
    t.inv_w[i] = inv_w;
    t.source[i] = v[i].source;
  }
  const std::int64_t area = edge(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
  if (area == 0) return std::nullopt;
  // y points down on screen, so a triangle counter-clockwise in NDC (front-facing) has a
  // negative area here; orient every kept triangle to positive area.
  if (area > 0 && culling == Culling::back_faces) return std::nullopt;
  if (area < 0) {
    std::swap(t.x[1], t.x[2]);
    std::swap(t.y[1], t.y[2]);
    std::swap(t.depth[1], t.depth[2]);
    std::swap(t.inv_w[1], t.inv_w[2]);
    std::swap(t.source[1], t.source[2]);
  }
  return t;
}

void rasterize_triangle(const ScreenTriangle& t, const RasterTarget& target) {
  const auto [min_x, max_x] = std::minmax({t.x[0], t.x[1], t.x[2]});
  const auto [min_y, max_y] = std::minmax({t.y[0], t.y[1], t.y[2]});
  // Pixels whose centre px * 256 + 128 lies inside the box, within the target.
  const int x_begin = static_cast<int>(std::max<std::int64_t>(
      target.x0, -floor_div(-(min_x - kHalfPixel), kSubpixelScale)));
  const int x_end = static_cast<int>(
      std::min<std::int64_t>(target.x1, floor_div(max_x - kHalfPixel, kSubpixelScale) + 1));
  const int y_begin = static_cast<int>(std::max<std::int64_t>(
      target.y0, -floor_div(-(min_y - kHalfPixel), kSubpixelScale)));
  const int y_end = static_cast<int>(
      std::min<std::int64_t>(target.y1, floor_div(max_y - kHalfPixel, kSubpixelScale) + 1));
  if (x_begin >= x_end || y_begin >= y_end) return;

  const std::int64_t sx = static_cast<std::int64_t>(x_begin) * kSubpixelScale + kHalfPixel;
  const std::int64_t sy = static_cast<std::int64_t>(y_begin) * kSubpixelScale + kHalfPixel;
  const EdgeWalk e0 = walk_edge(t, 0, sx, sy), e1 = walk_edge(t, 1, sx, sy),
                 e2 = walk_edge(t, 2, sx, sy);
  // Depth is affine on screen: a plane walked in double (exact enough over a tile's 64 steps
  // to keep the float result correctly rounded, which the 1 km precision test relies on).
  const double inv_area = 1.0 / static_cast<double>(e0.at_start + e0.bias + e1.at_start +
                                                    e1.bias + e2.at_start + e2.bias);
  const double z_start = (static_cast<double>(e0.at_start + e0.bias) * t.depth[0] +
                          static_cast<double>(e1.at_start + e1.bias) * t.depth[1] +
                          static_cast<double>(e2.at_start + e2.bias) * t.depth[2]) * inv_area;
  const double z_dx = (static_cast<double>(e0.step_x) * t.depth[0] +
                       static_cast<double>(e1.step_x) * t.depth[1] +
                       static_cast<double>(e2.step_x) * t.depth[2]) * inv_area;
  const double z_dy = (static_cast<double>(e0.step_y) * t.depth[0] +
                       static_cast<double>(e1.step_y) * t.depth[1] +
                       static_cast<double>(e2.step_y) * t.depth[2]) * inv_area;
  const int stride = target.stride > 0 ? target.stride : target.x1 - target.x0;
  std::int64_t r0 = e0.at_start, r1 = e1.at_start, r2 = e2.at_start;
  double row_z = z_start;
  for (int y = y_begin; y < y_end; ++y) {
    std::int64_t w0 = r0, w1 = r1, w2 = r2;
    double z = row_z;
    const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(y - target.y0) * stride - target.x0;
    for (int x = x_begin; x < x_end; ++x) {
      if ((w0 | w1 | w2) >= 0 && static_cast<float>(z) > target.depth[row + x]) {  // in, nearer
        target.depth[row + x] = static_cast<float>(z);
        if (target.ids) target.ids[row + x] = target.id_value;
      }
      w0 += e0.step_x;
      w1 += e1.step_x;
      w2 += e2.step_x;
      z += z_dx;
    }
    r0 += e0.step_y;
    r1 += e1.step_y;
    r2 += e2.step_y;
    row_z += z_dy;
  }
}

glm::vec3 source_barycentrics(const ScreenTriangle& t, float px, float py) {
  const double x = static_cast<double>(px) * kSubpixelScale;
  const double y = static_cast<double>(py) * kSubpixelScale;
  double l[3];
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    l[k] = ((static_cast<double>(t.x[b]) - t.x[a]) * (y - t.y[a]) -
            (static_cast<double>(t.y[b]) - t.y[a]) * (x - t.x[a])) * t.inv_w[k];
  }
  const double sum = l[0] + l[1] + l[2];
  const glm::dvec3 b = glm::dvec3(l[0], l[1], l[2]) / sum;  // weights of the screen corners
  // Map to the scene triangle: each screen corner has known weights in it.
  glm::dvec2 s(0.0);
  for (int k = 0; k < 3; ++k) s += b[k] * glm::dvec2(t.source[k]);
  return {static_cast<float>(1.0 - s.x - s.y), static_cast<float>(s.x), static_cast<float>(s.y)};
}

}  // namespace roomcad
