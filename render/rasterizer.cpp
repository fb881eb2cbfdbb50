// SPDX-License-Identifier: GPL-3.0-or-later
// Edge-function rasterisation in fixed point, with the top-left rule and reversed-Z depth.
#include "render/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/detail/wide_loops.h"

namespace roomcad {
namespace {

constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;

/// floor(a / b) for b > 0, also for negative a.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/// The first pixel whose centre (pixel * 256 + 128) is at or after fixed-point `lo`.
std::int64_t first_centre(std::int64_t lo) {
  return -floor_div(-(lo - kHalfPixel), kSubpixelScale);
}

/// The last pixel whose centre is at or before fixed-point `hi`.
std::int64_t last_centre(std::int64_t hi) { return floor_div(hi - kHalfPixel, kSubpixelScale); }

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

/// Depth at the first pixel centre of the box and its change per pixel across and down.
struct DepthPlane {
  double start = 0.0, dx = 0.0, dy = 0.0;
};

/// Depth is affine on screen; the plane is kept in double so that each row starts correctly
/// rounded (the 1 km precision test relies on depth within a few float ulps).
DepthPlane depth_plane(const ScreenTriangle& t, const std::array<EdgeWalk, 3>& e) {
  double area = 0.0;
  DepthPlane p;
  for (int k = 0; k < 3; ++k) {
    area += static_cast<double>(e[k].at_start + e[k].bias);
    p.start += static_cast<double>(e[k].at_start + e[k].bias) * t.depth[k];
    p.dx += static_cast<double>(e[k].step_x) * t.depth[k];
    p.dy += static_cast<double>(e[k].step_y) * t.depth[k];
  }
  const double inv_area = 1.0 / area;  // one division, not three
  return {p.start * inv_area, p.dx * inv_area, p.dy * inv_area};
}

/// The bound one edge puts on the pixels of each row of the box, kept exact from row to row
/// by integer steps (a DDA) rather than a division per row. Pixel i of a row is inside the
/// edge when w + i * step_x >= 0 (w: the edge at the row's first pixel centre), that is
/// i >= ceil(-w / step_x) for step_x > 0 (a left bound), i < ceil((w + 1) / -step_x) for
/// step_x < 0 (a right bound), and any i (w >= 0) or none for step_x == 0. The bound is
/// q = ceil(n / d) for a numerator n that moves by a constant each row; with its remainder
/// r = q d - n in [0, d) it follows in two additions and a compare.
class EdgeSpan {
 public:
  explicit EdgeSpan(const EdgeWalk& e) {
    if (e.step_x == 0) {  // flat: the row is all in or all out
      w_ = e.at_start;
      step_ = e.step_y;
      return;
    }
    kind_ = e.step_x > 0 ? Kind::left : Kind::right;
    d_ = e.step_x > 0 ? e.step_x : -e.step_x;
    const std::int64_t n = kind_ == Kind::left ? -e.at_start : e.at_start + 1;
    const std::int64_t n_step = kind_ == Kind::left ? -e.step_y : e.step_y;
    q_ = -floor_div(-n, d_);  // ceil(n / d)
    r_ = q_ * d_ - n;
    q_step_ = floor_div(n_step, d_);  // n_step = q_step d + r_step, 0 <= r_step < d
    r_step_ = n_step - q_step_ * d_;
  }

  /// Narrows the row's pixels [lo, hi) to those inside the edge.
  void narrow(std::int64_t& lo, std::int64_t& hi) const {
    switch (kind_) {
      case Kind::left: lo = std::max(lo, q_); break;
      case Kind::right: hi = std::min(hi, q_); break;
      case Kind::flat:
        if (w_ < 0) hi = lo;
        break;
    }
  }

  /// Moves to the next row.
  void step() {
    if (kind_ == Kind::flat) {
      w_ += step_;
      return;
    }
    q_ += q_step_;
    r_ -= r_step_;
    const bool under = r_ < 0;  // one more step of the quotient puts r back in [0, d)
    q_ += under;
    r_ += under ? d_ : 0;
  }

 private:
  enum class Kind { left, right, flat };
  Kind kind_ = Kind::flat;
  std::int64_t q_ = 0, r_ = 0, d_ = 1, q_step_ = 0, r_step_ = 0;  // left and right
  std::int64_t w_ = 0, step_ = 0;                                 // flat
};

/// Depth-tests pixels [lo, hi) of a row whose depth is z0 + i * dz at pixel i (reversed-Z: a
/// greater depth is nearer) and keeps the nearer. Every pixel is stored, changed or not, and
/// the id is selected with a mask, so the compiler turns the loop into SSE2 without branches.
void test_span(float z0, float dz, int lo, int hi, float* depth, std::uint32_t* ids,
               std::uint32_t id) {
  for (int i = lo; i < hi; ++i) {
    const float z = z0 + static_cast<float>(i) * dz;
    const std::uint32_t nearer = 0u - static_cast<std::uint32_t>(z > depth[i]);  // all ones
    depth[i] = std::max(depth[i], z);
    ids[i] = (ids[i] & ~nearer) | (id & nearer);
  }
}

/// test_span without ids (shadow maps).
void test_span_depth_only(float z0, float dz, int lo, int hi, float* depth) {
  for (int i = lo; i < hi; ++i) {
    const float z = z0 + static_cast<float>(i) * dz;
    depth[i] = std::max(depth[i], z);
  }
}

/// round(v) for the set-up's fixed point, ties away from zero as std::lround, but inline
/// (lround is a library call, six per triangle). |v| < 2^30.
std::int32_t round_to_fixed(double v) {
  const double shifted = v < 0.0 ? v - 0.5 : v + 0.5;
  return static_cast<std::int32_t>(shifted);  // truncation towards zero completes the rounding
}

}  // namespace

bool covers_no_sample(const ScreenTriangle& t) {
  const auto [min_x, max_x] = std::minmax({t.x[0], t.x[1], t.x[2]});
  const auto [min_y, max_y] = std::minmax({t.y[0], t.y[1], t.y[2]});
  return first_centre(min_x) > last_centre(max_x) || first_centre(min_y) > last_centre(max_y);
}

std::optional<ScreenTriangle> set_up_triangle(const std::array<ClipVertex, 3>& v, int width,
                                              int height, std::uint32_t triangle, Culling culling) {
  ScreenTriangle t;
  t.triangle = triangle;
  for (int i = 0; i < 3; ++i) {
    const glm::vec4& p = v[i].position;
    const float inv_w = 1.f / p.w;
    const double sx = (static_cast<double>(p.x) * inv_w + 1.0) * 0.5 * width;
    const double sy = (1.0 - static_cast<double>(p.y) * inv_w) * 0.5 * height;
    // Not a number, or past the fixed point's range (a light's view fitted to a scene whose
    // bounds overflow, such as one with a corner 5e306 m out): nothing to draw.
    constexpr double kLimit = 0x1p30 / kSubpixelScale;  // round_to_fixed's
    if (!(std::abs(sx) < kLimit && std::abs(sy) < kLimit)) return std::nullopt;
    t.x[i] = round_to_fixed(sx * kSubpixelScale);
    t.y[i] = round_to_fixed(sy * kSubpixelScale);
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

ROOMCAD_WIDE_LOOPS void rasterize_triangle(const ScreenTriangle& t, const RasterTarget& target) {
  const auto [min_x, max_x] = std::minmax({t.x[0], t.x[1], t.x[2]});
  const auto [min_y, max_y] = std::minmax({t.y[0], t.y[1], t.y[2]});
  // Pixels whose centre px * 256 + 128 lies inside the box, within the target.
  const int x_begin = static_cast<int>(std::max<std::int64_t>(target.x0, first_centre(min_x)));
  const int x_end = static_cast<int>(std::min<std::int64_t>(target.x1, last_centre(max_x) + 1));
  const int y_begin = static_cast<int>(std::max<std::int64_t>(target.y0, first_centre(min_y)));
  const int y_end = static_cast<int>(std::min<std::int64_t>(target.y1, last_centre(max_y) + 1));
  if (x_begin >= x_end || y_begin >= y_end) return;

  const std::int64_t sx = static_cast<std::int64_t>(x_begin) * kSubpixelScale + kHalfPixel;
  const std::int64_t sy = static_cast<std::int64_t>(y_begin) * kSubpixelScale + kHalfPixel;
  const std::array<EdgeWalk, 3> e{walk_edge(t, 0, sx, sy), walk_edge(t, 1, sx, sy),
                                  walk_edge(t, 2, sx, sy)};
  const DepthPlane plane = depth_plane(t, e);
  const int stride = target.stride > 0 ? target.stride : target.x1 - target.x0;
  std::array<EdgeSpan, 3> spans{EdgeSpan(e[0]), EdgeSpan(e[1]), EdgeSpan(e[2])};
  for (int y = y_begin; y < y_end; ++y) {
    // The row's span: the pixels where all three (biased) edge functions are >= 0.
    const std::int64_t box_width = x_end - x_begin;
    std::int64_t lo_edge = 0, hi_edge = box_width;
    for (EdgeSpan& span : spans) {
      span.narrow(lo_edge, hi_edge);
      span.step();
    }
    // Every row of the box meets the triangle, so the bounds stay within a pixel of the box
    // (a right bound of a nearly level edge lies far beyond it, but min() took care of that);
    // the clamp only makes the narrowing to int safe by construction.
    const int lo = static_cast<int>(std::min(lo_edge, box_width));
    const int hi = static_cast<int>(std::max<std::int64_t>(lo, hi_edge));
    const std::ptrdiff_t row =
        static_cast<std::ptrdiff_t>(y - target.y0) * stride + (x_begin - target.x0);
    // The row's depth in double, then float across the span (a vector of pixels per step):
    // at most a tile wide, that adds a few float ulps to the correctly rounded value.
    const float row_z = static_cast<float>(plane.start + (y - y_begin) * plane.dy);
    const float dx = static_cast<float>(plane.dx);
    if (target.ids) {
      test_span(row_z, dx, lo, hi, target.depth + row, target.ids + row, target.id_value);
    } else {
      test_span_depth_only(row_z, dx, lo, hi, target.depth + row);
    }
  }
}

std::optional<float> depth_at_pixel(const ScreenTriangle& t, int px, int py, int x0, int y0) {
  const auto min_x = std::min({t.x[0], t.x[1], t.x[2]});
  const auto min_y = std::min({t.y[0], t.y[1], t.y[2]});
  // rasterize_triangle's box start and edge walks from it, so the depth rounds the same way
  const std::int64_t x_begin = std::max<std::int64_t>(x0, first_centre(min_x));
  const std::int64_t y_begin = std::max<std::int64_t>(y0, first_centre(min_y));
  if (px < x_begin || py < y_begin) return std::nullopt;
  const std::int64_t sx = x_begin * kSubpixelScale + kHalfPixel;
  const std::int64_t sy = y_begin * kSubpixelScale + kHalfPixel;
  const std::array<EdgeWalk, 3> e{walk_edge(t, 0, sx, sy), walk_edge(t, 1, sx, sy),
                                  walk_edge(t, 2, sx, sy)};
  const std::int64_t i = px - x_begin, j = py - y_begin;
  for (const EdgeWalk& w : e) {
    if (w.at_start + i * w.step_x + j * w.step_y < 0) return std::nullopt;
  }
  const DepthPlane plane = depth_plane(t, e);
  const float row_z = static_cast<float>(plane.start + static_cast<double>(j) * plane.dy);
  return row_z + static_cast<float>(i) * static_cast<float>(plane.dx);
}

BarycentricPlanes barycentric_planes(const ScreenTriangle& t) {
  BarycentricPlanes p;
  for (int k = 0; k < 3; ++k) {  // edge function k over pixels, divided by corner k's w
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const double dx = static_cast<double>(t.x[b]) - t.x[a],
                 dy = static_cast<double>(t.y[b]) - t.y[a];
    const glm::dvec3 e =
        glm::dvec3(-dy * kSubpixelScale, dx * kSubpixelScale, dy * t.x[a] - dx * t.y[a]) *
        static_cast<double>(t.inv_w[k]);
    p.denominator += e;
    p.weight1 += e * static_cast<double>(t.source[k].x);
    p.weight2 += e * static_cast<double>(t.source[k].y);
  }
  return p;
}

glm::vec3 source_barycentrics(const ScreenTriangle& t, float px, float py) {
  return barycentric_planes(t).at(px, py);
}

}  // namespace roomcad
