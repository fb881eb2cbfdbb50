// SPDX-License-Identifier: GPL-3.0-or-later
// Clipping and rasterisation: near-plane clipping without mirrored vertices, the top-left rule
// (shared edges drawn exactly once), back-face culling and perspective-correct weights.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "render/clip.h"
#include "render/rasterizer.h"

namespace roomcad {
namespace {

/// A clip-space vertex of an orthographic-like view (w = 1) at screen NDC (x, y).
ClipVertex ndc(float x, float y, float z = 0.5f, float w = 1.f) {
  return {glm::vec4(x * w, y * w, z * w, w), glm::vec2(0.f)};
}

/// Number of pixels a triangle covers in a fresh width x height buffer.
std::vector<int> coverage(const ScreenTriangle& t, int width, int height) {
  std::vector<float> depth(static_cast<std::size_t>(width) * height, 0.f);
  rasterize_triangle(t, RasterTarget{.x0 = 0,
                                     .y0 = 0,
                                     .x1 = width,
                                     .y1 = height,
                                     .depth = depth.data(),
                                     .ids = nullptr,
                                     .id_value = 0});
  std::vector<int> covered(depth.size());
  for (std::size_t i = 0; i < depth.size(); ++i) covered[i] = depth[i] > 0.f ? 1 : 0;
  return covered;
}

TEST(Render, ClipKeepsTheFrontPartOfATriangleCrossingTheNearPlane) {
  // Near plane: w - z >= 0. Corner 0 is behind the eye (w < 0): dividing it would mirror it.
  const std::array<ClipVertex, 3> tri{{{glm::vec4(0.f, 0.f, 0.05f, -1.f), {0.f, 0.f}},
                                       {glm::vec4(-0.5f, 0.f, 0.05f, 2.f), {1.f, 0.f}},
                                       {glm::vec4(0.5f, 0.f, 0.05f, 2.f), {0.f, 1.f}}}};
  const ClipPolygon poly = clip_triangle(tri);
  ASSERT_GE(poly.count, 3);  // cut by the near plane and, behind the eye, by the sides
  for (int i = 0; i < poly.count; ++i) {
    const glm::vec4& p = poly.vertices[i].position;
    EXPECT_GE(p.w - p.z, -1e-6f);  // in front of the near plane (up to rounding)
    EXPECT_GT(p.w, 0.f);           // nothing left behind the eye
    EXPECT_GE(p.w - std::abs(p.x), -1e-6f);
    EXPECT_GE(p.w - std::abs(p.y), -1e-6f);
  }
}

TEST(Render, ClipDropsATriangleWhollyOutside) {
  const std::array<ClipVertex, 3> tri{{ndc(2.f, 0.f), ndc(3.f, 0.f), ndc(2.f, 1.f)}};
  EXPECT_EQ(clip_triangle(tri).count, 0);
}

TEST(Render, SharedEdgesThroughPixelCentresAreDrawnExactlyOnce) {
  const int w = 16, h = 16;
  // A square whose corners and diagonal pass exactly through pixel centres, split along the
  // diagonal, plus a triangle sharing its right edge: no pixel is drawn twice, and every
  // centre inside the square (on the diagonal too) is drawn once.
  auto at = [&](float px, float py) { return ndc(px / w * 2.f - 1.f, 1.f - py / h * 2.f); };
  const std::vector<std::array<ClipVertex, 3>> tris = {
      {at(2.5f, 2.5f), at(12.5f, 2.5f), at(12.5f, 12.5f)},
      {at(2.5f, 2.5f), at(12.5f, 12.5f), at(2.5f, 12.5f)},
      {at(12.5f, 2.5f), at(15.5f, 7.5f), at(12.5f, 12.5f)}};
  std::vector<int> total(static_cast<std::size_t>(w) * h, 0);
  for (const auto& tri : tris) {
    const auto t = set_up_triangle(tri, w, h, 0, Culling::none);
    ASSERT_TRUE(t.has_value());
    const std::vector<int> c = coverage(*t, w, h);
    for (std::size_t i = 0; i < c.size(); ++i) total[i] += c[i];
  }
  for (int v : total) EXPECT_LE(v, 1);
  for (int y = 2; y <= 11; ++y) {
    for (int x = 2; x <= 12; ++x) {
      if (x == 12 && y == 2) continue;  // the union's top-right corner: neither top nor left
      EXPECT_EQ(total[y * w + x], 1) << "pixel " << x << "," << y;
    }
  }
  EXPECT_EQ(total[2 * w + 12], 0);
  EXPECT_EQ(total[12 * w + 5], 0);  // the bottom edge is not a top edge: left out
}

/// Whether pixel (px, py)'s centre is inside t by the top-left rule, straight from the edge
/// functions (the reference the rasteriser's stepped spans must agree with).
bool covers_centre(const ScreenTriangle& t, std::int64_t px, std::int64_t py) {
  const std::int64_t cx = px * kSubpixelScale + kSubpixelScale / 2;
  const std::int64_t cy = py * kSubpixelScale + kSubpixelScale / 2;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const std::int64_t ax = t.x[a], ay = t.y[a], bx = t.x[b], by = t.y[b];
    const bool top_left = ay > by || (ay == by && bx > ax);
    const std::int64_t e = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (e - (top_left ? 0 : 1) < 0) return false;
  }
  return true;
}

TEST(Render, SteppedSpansOfHugeTrianglesMatchTheEdgeFunctions) {
  // The rasteriser steps each edge's bound from row to row (quotient and remainder); over a
  // thousand rows of a triangle as wide as the largest image, with an edge one 256th of a
  // pixel from level (its line meets a row 1000 pixels away 2^32 pixels off), any slip would
  // show. Windows of 64 x 64 at both ends and the middle, in four mirror images, must cover
  // exactly the centres the edge functions say.
  constexpr std::int32_t kWide = 16384 * kSubpixelScale, kTall = 1000 * kSubpixelScale;
  for (const bool flip_x : {false, true}) {
    for (const bool flip_y : {false, true}) {
      ScreenTriangle t;
      t.x = {0, kWide, kWide / 2};
      t.y = {1, 0, kTall};  // corners 0 and 1: one subpixel apart in y
      t.depth = {0.5f, 0.5f, 0.5f};
      for (auto& x : t.x) x = flip_x ? kWide - x : x;
      for (auto& y : t.y) y = flip_y ? kTall - y : y;
      const std::int64_t area = std::int64_t{t.x[1] - t.x[0]} * (t.y[2] - t.y[0]) -
                                std::int64_t{t.y[1] - t.y[0]} * (t.x[2] - t.x[0]);
      if (area < 0) std::swap(t.x[1], t.x[2]), std::swap(t.y[1], t.y[2]);
      for (const int window_x : {0, 8160, 16320}) {
        const int window_y = flip_y ? 936 : 0;  // next to the level edge, and far from it
        for (const int window_y2 : {window_y, 468}) {
          std::vector<float> depth(64 * 64, 0.f);
          rasterize_triangle(t, RasterTarget{.x0 = window_x,
                                             .y0 = window_y2,
                                             .x1 = window_x + 64,
                                             .y1 = window_y2 + 64,
                                             .depth = depth.data()});
          int wrong = 0;
          for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
              wrong += (depth[y * 64 + x] > 0.f) != covers_centre(t, window_x + x, window_y2 + y);
            }
          }
          EXPECT_EQ(wrong, 0) << "flip " << flip_x << flip_y << " window " << window_x << ","
                              << window_y2;
        }
      }
    }
  }
}

TEST(Render, ATriangleWithACornerThatIsNotANumberIsNotSetUp) {
  const ClipVertex a = ndc(-0.5f, -0.5f), b = ndc(0.5f, -0.5f), c = ndc(0.f, 0.5f);
  ClipVertex bad = c;
  bad.position.x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(set_up_triangle({a, b, c}, 32, 32, 0, Culling::none).has_value());
  EXPECT_FALSE(set_up_triangle({a, b, bad}, 32, 32, 0, Culling::none).has_value());
  bad.position = {1e30f, 0.f, 0.5f, 1.f};  // past the fixed point's range
  EXPECT_FALSE(set_up_triangle({a, b, bad}, 32, 32, 0, Culling::none).has_value());
}

TEST(Render, BackFacesAreCulledAndFrontFacesKept) {
  const ClipVertex a = ndc(-0.5f, -0.5f), b = ndc(0.5f, -0.5f), c = ndc(0.f, 0.5f);
  EXPECT_TRUE(set_up_triangle({a, b, c}, 32, 32, 0, Culling::back_faces).has_value());  // CCW
  EXPECT_FALSE(set_up_triangle({a, c, b}, 32, 32, 0, Culling::back_faces).has_value());
  EXPECT_TRUE(set_up_triangle({a, c, b}, 32, 32, 0, Culling::none).has_value());
}

TEST(Render, PerspectiveCorrectWeightsFollowDepthNotScreenDistance) {
  // Corner 1 is four times further (w = 4) than corners 0 and 2: at the screen midpoint of
  // edge 0-1 the true (world) weight of corner 1 is 1 / (1 + 4) = 0.2, not 0.5.
  ClipVertex v0 = ndc(-0.5f, -0.5f, 0.5f, 1.f), v1 = ndc(0.5f, -0.5f, 0.5f, 4.f),
             v2 = ndc(-0.5f, 0.5f, 0.5f, 1.f);
  v1.source = {1.f, 0.f};
  v2.source = {0.f, 1.f};
  const auto t = set_up_triangle({v0, v1, v2}, 100, 100, 0, Culling::none);
  ASSERT_TRUE(t.has_value());
  const glm::vec3 weights = source_barycentrics(*t, 50.f, 75.f);  // screen midpoint of 0-1
  EXPECT_NEAR(weights[1], 0.2f, 1e-4f);
  EXPECT_NEAR(weights[0], 0.8f, 1e-4f);
  EXPECT_NEAR(weights[2], 0.f, 1e-4f);
}

}  // namespace
}  // namespace roomcad
