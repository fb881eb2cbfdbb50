// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/mesh_check.h"

#include <gtest/gtest.h>

#include <array>

namespace roomcad {
namespace {

using V = OpenMesh::Vec3d;

// A box [0, 2] x [0, 1] x [0, 1] at (dx, dy, dz); `skip` drops one face, `flip` reverses all.
void add_box(SolidMesh& mesh, double dx, int skip = -1, bool flip = false, double dy = 0.0,
             double dz = 0.0) {
  std::array<SolidMesh::VertexHandle, 8> v;
  for (int k = 0; k < 8; ++k)
    v[k] = mesh.add_vertex(
        V(dx + 2.0 * ((k & 1) != 0), dy + ((k & 2) ? 1 : 0), dz + ((k & 4) ? 1 : 0)));
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int f = 0; f < 6; ++f) {
    if (f == skip) continue;
    std::vector<SolidMesh::VertexHandle> face;
    for (int k = 0; k < 4; ++k) face.push_back(v[faces[f][flip ? 3 - k : k]]);
    mesh.add_face(face);
  }
}

SolidMesh with_normals(SolidMesh mesh) {
  mesh.request_face_normals();
  mesh.update_face_normals();
  return mesh;
}

TEST(MeshCheck, BoxIsValid) {
  SolidMesh mesh;
  add_box(mesh, 0.0);
  const SolidCheck c = check_solid(with_normals(mesh));
  EXPECT_TRUE(c.is_valid());
  EXPECT_EQ(c.triangles, 12u);
  EXPECT_EQ(c.genus, 0);
  EXPECT_DOUBLE_EQ(c.volume, 2.0);
}

TEST(MeshCheck, OpenBoxIsNotClosed) {
  SolidMesh mesh;
  add_box(mesh, 0.0, 3);
  const SolidCheck c = check_solid(with_normals(mesh));
  EXPECT_FALSE(c.is_closed());
  EXPECT_FALSE(c.is_valid());
}

TEST(MeshCheck, InsideOutBoxIsFlagged) {
  SolidMesh mesh;
  add_box(mesh, 0.0, -1, true);
  const SolidCheck c = check_solid(with_normals(mesh));
  EXPECT_EQ(c.inward_components, 1u);
  EXPECT_DOUBLE_EQ(c.volume, -2.0);
}

// A box [-1, 3] x [-1, 2] x [-1, 2] round the box of add_box: a shell with a void inside.
void add_outer_box(SolidMesh& mesh) {
  std::array<SolidMesh::VertexHandle, 8> v;
  for (int k = 0; k < 8; ++k)
    v[k] = mesh.add_vertex(V((k & 1) ? 3 : -1, (k & 2) ? 2 : -1, (k & 4) ? 2 : -1));
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) mesh.add_face({v[f[0]], v[f[1]], v[f[2]], v[f[3]]});
}

TEST(MeshCheck, AVoidInsideIsACavityNotAnInwardComponent) {
  // A room closed by its walls, floor and ceiling: the void's shell faces inward, rightly.
  SolidMesh mesh;
  add_outer_box(mesh);
  add_box(mesh, 0.0, -1, true);
  const SolidCheck c = check_solid(with_normals(mesh));
  EXPECT_EQ(c.cavities, 1u);
  EXPECT_EQ(c.inward_components, 0u);
  EXPECT_TRUE(c.is_valid());
  EXPECT_DOUBLE_EQ(c.volume, 4.0 * 3.0 * 3.0 - 2.0);
}

TEST(MeshCheck, AVoidFacingOutwardIsFlagged) {
  // The inner shell facing out: a box inside a box, not a solid with a void.
  SolidMesh mesh;
  add_outer_box(mesh);
  add_box(mesh, 0.0);
  add_box(mesh, 10.0, -1, true);  // and one inside out on its own
  const SolidCheck c = check_solid(with_normals(mesh));
  EXPECT_EQ(c.cavities, 0u);
  EXPECT_EQ(c.inward_components, 2u);
  EXPECT_FALSE(c.is_valid());
}

TEST(MeshCheck, OverlappingBoxesSelfIntersect) {
  SolidMesh mesh;
  add_box(mesh, 0.0);
  add_box(mesh, 1.0);
  const SolidCheck c = check_solid(with_normals(mesh));
  EXPECT_GT(c.self_intersections, 0u);
  EXPECT_EQ(c.components, 2u);
  EXPECT_FALSE(c.is_valid());
}

// Boxes touching along an edge or at a corner, each with its own vertices there: the faces
// meet at points both hold, which is touching, not crossing.
TEST(MeshCheck, BoxesTouchingAlongAnEdgeOrAtACornerDoNotSelfIntersect) {
  for (const double dz : {0.0, 1.0}) {
    SCOPED_TRACE(dz == 0.0 ? "along an edge" : "at a corner");
    SolidMesh mesh;
    add_box(mesh, 0.0);
    add_box(mesh, 2.0, -1, false, 1.0, dz);
    const SolidCheck c = check_solid(with_normals(mesh));
    EXPECT_EQ(c.self_intersections, 0u);
    EXPECT_GT(c.touching_pairs, 0u);
    EXPECT_TRUE(c.is_valid());
  }
}

// Two triangles holding the same point (separate vertices), one passing through the other
// beside it, or lying over it in its plane: crossing, however they touch.
TEST(MeshCheck, TrianglesHoldingAPointOrEdgeAndCrossingSelfIntersect) {
  const V o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  const std::vector<std::array<V, 3>> others{
      {o, V(0.3, 0.3, -1), V(0.3, 0.3, 1)},  // a point shared, through the first beside it
      {o, x, V(0.5, 0.2, 0)},                // an edge shared, over it in its plane
  };
  for (const auto& other : others) {
    SolidMesh mesh;
    const auto a = mesh.add_vertex(o), b = mesh.add_vertex(x), c = mesh.add_vertex(y);
    mesh.add_face(a, b, c);
    const auto d = mesh.add_vertex(other[0]), e = mesh.add_vertex(other[1]),
               f = mesh.add_vertex(other[2]);
    mesh.add_face(d, e, f);
    const SolidCheck check = check_solid(with_normals(mesh));
    EXPECT_EQ(check.self_intersections, 1u);
    EXPECT_EQ(check.touching_pairs, 0u);
  }
}

}  // namespace
}  // namespace roomcad
