// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/float_triangulation.h"

#include <gtest/gtest.h>

#include <map>

namespace roomcad {
namespace {

using V = OpenMesh::Vec3d;
using Key = std::array<float, 3>;

// The unit box at (10, 5, 0) (far enough from 0 that a float step is ~1e-6 m) whose top is a
// sliver triangle A B M and the rest A M B C D, with M = `m`, just above the front top edge AB.
SolidMesh box_with_top_sliver(const V& m) {
  SolidMesh mesh;
  auto add = [&](double x, double y, double z) { return mesh.add_vertex(V(10 + x, 5 + y, z)); };
  const auto b0 = add(0, 0, 0), b1 = add(1, 0, 0), b2 = add(1, 1, 0), b3 = add(0, 1, 0);
  const auto a = add(0, 0, 1), b = add(1, 0, 1), c = add(1, 1, 1), d = add(0, 1, 1);
  const auto sliver = mesh.add_vertex(m);
  using Ring = std::vector<SolidMesh::VertexHandle>;
  for (const Ring& face :
       {Ring{b0, b3, b2, b1}, Ring{b0, b1, b, a}, Ring{b1, b2, c, b}, Ring{b2, b3, d, c},
        Ring{b3, b0, a, d}, Ring{a, b, sliver}, Ring{a, sliver, b, c, d}})
    mesh.add_face(face);
  mesh.request_face_normals();
  mesh.update_face_normals();
  return mesh;
}

Key key_of(const OpenMesh::Vec3f& p) { return {p[0], p[1], p[2]}; }

// What every float triangulation of a closed mesh must be: no flat triangle (exact test on the
// floats: repeated corner or zero cross product, which is exact for these small coordinates),
// every directed edge matched by exactly one reverse edge, and the enclosed volume.
void expect_closed_without_flat_triangles(const std::vector<FloatTriangle>& triangles,
                                          double volume) {
  std::map<std::array<Key, 2>, int> uses;
  double six_volume = 0.0;
  for (const FloatTriangle& t : triangles) {
    const OpenMesh::Vec3d a(t.corners[0]), b(t.corners[1]), c(t.corners[2]);
    const OpenMesh::Vec3d o(10, 5, 0);
    EXPECT_NE(OpenMesh::cross(b - a, c - a).sqrnorm(), 0.0) << a << " | " << b << " | " << c;
    six_volume += OpenMesh::dot(a - o, OpenMesh::cross(b - o, c - o));
    for (int k = 0; k < 3; ++k) ++uses[{key_of(t.corners[k]), key_of(t.corners[(k + 1) % 3])}];
  }
  for (const auto& [edge, count] : uses) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(uses.count({edge[1], edge[0]}) ? uses.at({edge[1], edge[0]}) : 0, 1);
  }
  EXPECT_NEAR(six_volume / 6.0, volume, 1e-12);
}

TEST(FloatTriangulation, AMeshExactInFloatIsEarClippedAsIs) {
  const SolidMesh mesh = box_with_top_sliver(V(10.5, 5.5, 1));  // a plain top, fanned
  const auto triangles = triangulate_in_float(mesh);
  EXPECT_EQ(triangles.size(), 14u);  // 2 for the bottom and each side, 1 for ABM, 3 for AMBCD
  expect_closed_without_flat_triangles(triangles, 1.0);
}

// A sliver 1e-9 m wide, as where two walls meet at a slant: in float M lies on AB, so the
// triangle ABM is flat. It is dropped and M inserted into the front face's top edge.
TEST(FloatTriangulation, DropsASliverThatRoundsFlatAndSplitsTheEdgeAcross) {
  const SolidMesh mesh = box_with_top_sliver(V(10.5, 5 + 1e-9, 1));
  const auto triangles = triangulate_in_float(mesh);
  expect_closed_without_flat_triangles(triangles, 1.0);
  std::size_t front_at_m = 0;  // front-face triangles (y = 5, normal -y) with M as a corner
  for (const FloatTriangle& t : triangles)
    for (const auto& c : t.corners)
      front_at_m += mesh.normal(t.face)[1] < -0.5 && c == OpenMesh::Vec3f(10.5f, 5.f, 1.f);
  EXPECT_EQ(front_at_m, 2u);
}

// M within a float step of B: the sliver's ring collapses to two points and is dropped; the
// rest of the top loses its repeated corner.
TEST(FloatTriangulation, DropsAFaceWhoseCornersRoundTogether) {
  const SolidMesh mesh = box_with_top_sliver(V(11 - 4e-8, 5 + 1e-9, 1));
  const auto triangles = triangulate_in_float(mesh);
  EXPECT_EQ(triangles.size(), 12u);
  expect_closed_without_flat_triangles(triangles, 1.0);
}

TEST(FloatTriangulation, EmptyMeshGivesNoTriangles) {
  SolidMesh mesh;
  mesh.request_face_normals();
  EXPECT_TRUE(triangulate_in_float(mesh).empty());
}

// The unit box at (10, 5, 0) whose top is cut along x = 10.5 by a sliver S, as two walls'
// tops a micrometre apart leave it (arif-putra-pertama-1): S runs up its right side at x = 10.5
// and back down a left side that leans from 10.5 - 2e-7 (at y = 6 and 5.5) to 10.5 - 8e-7 (at
// y = 5). In float the upper left corners round onto the right side (a float step here is
// 9.5e-7): S's ring runs to (10.5, 6) and straight back, a spike whose edges would join the
// faces beside S a second time. The spike is cut off and S keeps the triangle that is left.
TEST(FloatTriangulation, CutsOffASpikeWhereRoundingClosesPartOfASliver) {
  SolidMesh mesh;
  auto add = [&](double x, double y, double z) { return mesh.add_vertex(V(x, y, z)); };
  const auto b0 = add(10, 5, 0), b1 = add(11, 5, 0), b2 = add(11, 6, 0), b3 = add(10, 6, 0);
  const auto a = add(10, 5, 1), b = add(11, 5, 1), c = add(11, 6, 1), d = add(10, 6, 1);
  const auto p1 = add(10.5, 5, 1), p2 = add(10.5, 5.5, 1), p3 = add(10.5, 6, 1);
  const auto q3 = add(10.5 - 2e-7, 6, 1), q2 = add(10.5 - 2e-7, 5.5, 1),
             q1 = add(10.5 - 8e-7, 5, 1);
  using Ring = std::vector<SolidMesh::VertexHandle>;
  for (const Ring& face : {Ring{b0, b3, b2, b1}, Ring{b0, b1, b, p1, q1, a}, Ring{b1, b2, c, b},
                           Ring{b2, b3, d, q3, p3, c}, Ring{b3, b0, a, d}, Ring{a, q1, q2, q3, d},
                           Ring{p1, b, c, p3, p2}, Ring{p1, p2, p3, q3, q2, q1}})
    mesh.add_face(face);
  mesh.request_face_normals();
  mesh.update_face_normals();
  const auto triangles = triangulate_in_float(mesh);
  expect_closed_without_flat_triangles(triangles, 1.0);
}

}  // namespace
}  // namespace roomcad
