// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh writers read back: every bundled example and imported home is written in each format,
// read with the small readers of mesh_read_support.h (no code shared with io/mesh_export), and
// compared with the model in memory: vertices, faces, colours, groups, normals, and the closed
// wall solid's volume against the volume computed from the plan alone.
#include "io/mesh_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "io/mesh_read_support.h"
#include "io/mesh_readback_support.h"
#include "support/solid_tolerance.h"

namespace roomcad {
namespace {

using test::ExpectedMesh;
using test::FloatPoint;
using test::Point3;
using test::ReadMesh;

// The first vertex whose doubles differ, as text; "" when all are the same doubles.
std::string first_vertex_difference(const std::vector<Point3>& read,
                                    const std::vector<Point3>& expected) {
  for (std::size_t i = 0; i < std::min(read.size(), expected.size()); ++i)
    if (read[i] != expected[i]) {
      std::ostringstream out;
      out.precision(17);
      out << "vertex " << i << ": read " << read[i][0] << ' ' << read[i][1] << ' ' << read[i][2]
          << ", model " << expected[i][0] << ' ' << expected[i][1] << ' ' << expected[i][2];
      return out.str();
    }
  return read.size() == expected.size() ? "" : "vertex counts differ";
}

// The wall solid read back (its faces are those on its vertices, written first): as many faces
// as the model's, closed, and enclosing the volume computed from the plan alone.
void expect_wall_solid(const ReadMesh& read, const ExpectedMesh& e,
                       const test::BuiltExample& example) {
  std::vector<std::vector<std::size_t>> rings;
  for (const auto& face : read.faces)
    if (std::all_of(face.begin(), face.end(), [&](std::size_t v) { return v < e.wall_vertices; }))
      rings.push_back(face);
  EXPECT_EQ(rings.size(), e.wall_faces) << example.name;
  EXPECT_EQ(test::count_unpaired_edges(rings), 0u) << example.name;
  const double volume = test::enclosed_volume(test::wall_polygons(read, e.wall_vertices));
  EXPECT_GT(example.analytic_volume, 1.0) << example.name;
  EXPECT_NEAR(volume, example.analytic_volume, 1e-9 * example.analytic_volume)
      << example.name << ", m^3";
}

// OFF and PLY keep the model's order: faces, corners and colours compare one by one.
void expect_same_faces_in_order(const ReadMesh& read, const ExpectedMesh& e,
                                const std::string& name) {
  ASSERT_EQ(read.faces.size(), e.faces.size()) << name;
  std::size_t differing = 0, first = 0;
  for (std::size_t i = 0; i < e.faces.size(); ++i)
    if (read.faces[i] != e.faces[i].corners || read.colors[i] != e.faces[i].color)
      if (differing++ == 0) first = i;
  EXPECT_EQ(differing, 0u) << name << ": the first differing face is " << first;
}

void expect_off_reads_back(const test::BuiltExample& example, const ExpectedMesh& e) {
  const ReadMesh read = test::read_off(format_off(test::all_parts(example.model)));
  EXPECT_EQ(first_vertex_difference(read.vertices, e.vertices), "") << example.name;
  expect_same_faces_in_order(read, e, example.name);
  expect_wall_solid(read, e, example);
}

void expect_ply_reads_back(const test::BuiltExample& example, const ExpectedMesh& e) {
  const ReadMesh read = test::read_ply(format_ply(test::all_parts(example.model)));
  EXPECT_EQ(first_vertex_difference(read.vertices, e.vertices), "") << example.name;
  expect_same_faces_in_order(read, e, example.name);
  expect_wall_solid(read, e, example);
}

// OBJ writes faces group by group: each face must be there once with its corners, its colour
// (usemtl, then Kd in the MTL), its object group and its normal; each group is one block.
void expect_obj_reads_back(const test::BuiltExample& example, const ExpectedMesh& e) {
  const MeshParts parts = test::all_parts(example.model);
  const std::string obj = format_obj(parts, "model.mtl");
  EXPECT_EQ(obj.find("mtllib model.mtl\n"), obj.find('\n') + 1) << example.name;
  const ReadMesh read = test::read_obj(obj, format_mtl(parts));
  EXPECT_EQ(first_vertex_difference(read.vertices, e.vertices), "") << example.name;
  std::vector<test::ExpectedFace> faces;
  for (std::size_t i = 0; i < read.faces.size(); ++i)
    faces.push_back({read.faces[i], read.colors[i], read.groups[i], read.normals[i]});
  std::vector<test::ExpectedFace> expected = e.faces;
  std::sort(faces.begin(), faces.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_TRUE(faces == expected) << example.name << ": " << faces.size() << " faces read, "
                                 << expected.size() << " in the model";
  std::set<std::string> groups;
  for (const auto& f : e.faces) groups.insert(f.group);
  EXPECT_EQ(read.group_blocks.size(), groups.size()) << example.name;
  for (const auto& [group, blocks] : read.group_blocks) {
    EXPECT_TRUE(groups.count(group)) << example.name << ": group " << group;
    EXPECT_EQ(blocks, 1) << example.name << ": group " << group;
  }
  expect_wall_solid(read, e, example);
}

// One test for the three text formats: building the examples takes seconds, once per process.
TEST(MeshExport, ObjOffAndPlyReadBackAsTheModel) {
  const auto& examples = test::built_examples();
  std::set<std::string> names;
  for (const auto& e : examples) names.insert(e.name);
  // Imported homes too (the storeyed ones, version 2, join when the build reads it).
  for (const char* name : {"house", "flat", "Studio", "3-BedroomApartment"})
    EXPECT_TRUE(names.count(name)) << name << " is not among the examples";
  for (const auto& example : examples) {
    const ExpectedMesh e = test::expected_mesh(example.model);
    {
      SCOPED_TRACE("OFF");
      expect_off_reads_back(example, e);
    }
    {
      SCOPED_TRACE("PLY");
      expect_ply_reads_back(example, e);
    }
    SCOPED_TRACE("OBJ");
    expect_obj_reads_back(example, e);
  }
}

// How far rounding to float32 can move a coordinate of a mesh: one float step of its largest.
double float_rounding(const Model& model) {
  double largest = 0.0;
  for (const SolidMesh* mesh : {&model.walls, &model.floor, &model.fixtures})
    for (const auto v : mesh->vertices())
      for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(mesh->point(v)[k]));
  const float f = static_cast<float>(largest);
  return std::nextafter(f, 2 * f + 1) - f;
}

FloatPoint rounded(const OpenMesh::Vec3d& p) {
  return {static_cast<float>(p[0]) + 0.0f, static_cast<float>(p[1]) + 0.0f,
          static_cast<float>(p[2]) + 0.0f};
}

double area_of(const test::FloatTriangle3& t) {
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) u[k] = double(t[1][k]) - t[0][k], v[k] = double(t[2][k]) - t[0][k];
  return std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0]) /
         2;
}

double model_area(const Model& model) {
  double area = 0.0;
  for (const SolidMesh* mesh : {&model.walls, &model.floor, &model.fixtures})
    for (const auto& [kind, a] : test::area_by_kind(*mesh)) area += a;
  return area;
}

// STL (float32 triangles): no facet is flat (a repeated corner or three corners on a line,
// decided exactly), every corner is a model vertex rounded to float and every normal a model
// face normal rounded, and the facets cover the model's area up to what rounding allows.
void expect_stl_facets_of_the_model(const test::BuiltExample& example) {
  const Model& model = example.model;
  std::set<FloatPoint> corners, normals;
  for (const SolidMesh* mesh : {&model.walls, &model.floor, &model.fixtures}) {
    for (const auto v : mesh->vertices()) corners.insert(rounded(mesh->point(v)));
    for (const auto f : mesh->faces()) normals.insert(rounded(mesh->normal(f)));
  }
  const auto facets = test::read_stl(format_stl(test::all_parts(model)));
  std::size_t flat = 0, stray_corners = 0, stray_normals = 0;
  double area = 0.0, perimeter = 0.0;
  for (const auto& facet : facets) {
    flat += test::is_flat(facet.corners);
    stray_normals += !normals.count(facet.normal);
    for (const FloatPoint& c : facet.corners) stray_corners += !corners.count(c);
    area += area_of(facet.corners);
    for (int k = 0; k < 3; ++k) {
      const auto &a = facet.corners[std::size_t(k)], &b = facet.corners[std::size_t(k + 1) % 3];
      perimeter += std::hypot(double(a[0]) - b[0], double(a[1]) - b[1], double(a[2]) - b[2]);
    }
  }
  EXPECT_EQ(flat, 0u) << example.name;
  EXPECT_EQ(stray_corners, 0u) << example.name;
  EXPECT_EQ(stray_normals, 0u) << example.name;
  EXPECT_GE(facets.size(),
            model.walls.n_faces() + model.floor.n_faces() + model.fixtures.n_faces());
  // Moving each corner by at most d changes a triangle's area by at most its perimeter x d.
  EXPECT_NEAR(area, model_area(model), perimeter * float_rounding(model))
      << example.name << ", m^2";
}

// The wall solid in STL, welded by coordinates as an STL reader does: every edge joins exactly
// two facets, in opposite directions, and the volume is the plan's up to what rounding allows.
void expect_stl_wall_solid_closed(const test::BuiltExample& example) {
  const Model& model = example.model;
  const auto facets = test::read_stl(format_stl({{&model.walls}, &model.objects}));
  std::vector<std::vector<FloatPoint>> rings;
  std::vector<std::vector<Point3>> triangles;
  for (const auto& facet : facets) {
    rings.emplace_back(facet.corners.begin(), facet.corners.end());
    auto& t = triangles.emplace_back();
    for (const FloatPoint& c : facet.corners) t.push_back({c[0], c[1], c[2]});
  }
  EXPECT_EQ(test::count_unpaired_edges(rings), 0u) << example.name;
  double area = 0.0;
  for (const auto& [kind, a] : test::area_by_kind(model.walls)) area += a;
  const double tolerance = 1e-9 * example.analytic_volume + area * float_rounding(model);
  EXPECT_NEAR(test::enclosed_volume(triangles), example.analytic_volume, tolerance)
      << example.name << ", m^3";
}

TEST(MeshExport, StlIsTheModelRoundedClosedAndNeverFlat) {
  for (const auto& example : test::built_examples()) {
    expect_stl_facets_of_the_model(example);
    expect_stl_wall_solid_closed(example);
  }
}

}  // namespace
}  // namespace roomcad
