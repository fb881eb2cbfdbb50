// Clipping and rasterisation: near-plane clipping without mirrored vertices, the top-left rule
// (shared edges drawn exactly once), back-face culling and perspective-correct weights.
#include <gtest/gtest.h>

#include <cmath>
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
  rasterize_triangle(t, RasterTarget{.x0 = 0, .y0 = 0, .x1 = width, .y1 = height,
                                     .depth = depth.data(), .ids = nullptr, .id_value = 0});
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
