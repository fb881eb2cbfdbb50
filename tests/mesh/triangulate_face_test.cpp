// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/triangulate_face.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace roomcad {
namespace {

using V = OpenMesh::Vec3d;

// Twice the signed area of triangle t projected on z, for faces in the xy plane.
double signed_area_xy(const std::vector<V>& p, const std::array<int, 3>& t) {
  const V a = p[t[0]], b = p[t[1]], c = p[t[2]];
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double polygon_area_xy(const std::vector<V>& p) {
  double s = 0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    s += p[j][0] * p[i][1] - p[i][0] * p[j][1];
  return s;
}

void expect_valid_triangulation(const std::vector<V>& polygon) {
  const auto triangles = triangulate_face(polygon, V(0, 0, 1));
  ASSERT_EQ(triangles.size(), polygon.size() - 2);
  const double total = polygon_area_xy(polygon);
  double sum = 0;
  for (const auto& t : triangles) {
    const double a = signed_area_xy(polygon, t);
    EXPECT_GT(a * total, 0.0) << "triangle has zero area or the wrong orientation";
    sum += a;
  }
  EXPECT_NEAR(sum, total, 1e-12 * std::abs(total));
}

TEST(TriangulateFace, TriangulatesRectangleWithStraightVertices) {
  // A wall face carrying the vertices of its neighbours: points in the middle of its edges.
  expect_valid_triangulation({V(0, 0, 0), V(1, 0, 0), V(2, 0, 0), V(3, 0, 0), V(3, 1, 0),
                              V(3, 2, 0), V(1.5, 2, 0), V(0, 2, 0), V(0, 1, 0)});
}

TEST(TriangulateFace, TriangulatesNonConvexDoorNotch) {
  // A wall face with a door cut from its bottom edge: a U shape.
  expect_valid_triangulation({V(0, 0, 0), V(1, 0, 0), V(1, 2, 0), V(2, 2, 0), V(2, 0, 0),
                              V(3, 0, 0), V(3, 3, 0), V(0, 3, 0)});
}

TEST(TriangulateFace, KeepsClockwiseOrientation) {
  expect_valid_triangulation({V(0, 0, 0), V(0, 2, 0), V(2, 2, 0), V(2, 0, 0), V(1, 0, 0)});
}

TEST(TriangulateFace, TriangulatesVerticalFaceFarFromOrigin) {
  const double x0 = 1e6;
  const std::vector<V> face{V(x0, 5, 0), V(x0 + 4, 5, 0), V(x0 + 4, 5, 2.8), V(x0 + 2, 5, 2.8),
                            V(x0, 5, 2.8)};
  const auto triangles = triangulate_face(face, V(0, -1, 0));
  ASSERT_EQ(triangles.size(), 3u);
  for (const auto& t : triangles) {
    const V n = (face[t[1]] - face[t[0]]) % (face[t[2]] - face[t[0]]);
    EXPECT_LT(n[1], 0.0) << "orientation must follow the face (normal -y)";
  }
}

TEST(TriangulateFace, ZeroAreaPolygonGivesNoTriangles) {
  EXPECT_TRUE(
      triangulate_face(std::vector<V>{V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)}, V(0, 0, 1)).empty());
  EXPECT_TRUE(triangulate_face(std::vector<V>{V(0, 0, 0), V(1, 0, 0)}, V(0, 0, 1)).empty());
}

}  // namespace
}  // namespace roomcad
