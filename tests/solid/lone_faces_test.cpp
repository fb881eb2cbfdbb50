// SPDX-License-Identifier: GPL-3.0-or-later
// take_lone_faces (detail/lone_faces.h): a face whose interior no other polygon of its plane
// meets is a face of the solid as it is. Touching along an edge or at a corner is not meeting;
// overlapping by any area is. The faces taken out, with the 2D boolean of what is left, must
// cover what the boolean of everything covers, per side and owner.
#include "solid/detail/general_path/lone_faces.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "axis_plane.h"

namespace roomcad::detail {
namespace {

TEST(LoneFaces, InteriorsMeetOnlyWhereThePolygonsOverlapByAnArea) {
  AxisPlane p(2);
  const PlanePolygon a = p.rectangle(0, 0, 2, 1);
  EXPECT_TRUE(interiors_meet(p.set, a, p.rectangle(1, 0.5, 3, 2)));      // overlapping corners
  EXPECT_TRUE(interiors_meet(p.set, a, p.rectangle(0.5, 0.2, 1, 0.8)));  // one inside the other
  EXPECT_TRUE(interiors_meet(p.set, a, p.rectangle(0, 0, 2, 1)));        // the same
  EXPECT_TRUE(interiors_meet(p.set, a, p.rectangle(-1, 0.4, 3, 0.6)));   // a cross
  EXPECT_FALSE(interiors_meet(p.set, a, p.rectangle(2, 0, 3, 1)));       // along an edge
  EXPECT_FALSE(interiors_meet(p.set, a, p.rectangle(2, 0.5, 3, 4)));     // along part of one
  EXPECT_FALSE(interiors_meet(p.set, a, p.rectangle(2, 1, 3, 2)));       // at a corner
  EXPECT_FALSE(interiors_meet(p.set, a, p.rectangle(5, 5, 6, 6)));       // apart
  // A mitre: the corner (2, 1) of one cut along the line x + y = 2.5, and a polygon beyond
  // that line touching it along the cut, or crossing it by a sliver.
  const PlanePolygon mitred = p.corner_cut(0, 0, 2, 1, 0.5, 0).polygon;
  PlaneRecipe cut;
  cut.kind = PlaneRecipe::Kind::through2;  // the mitre's line, from (2, 0.5) to (1.5, 1): x + y
                                           // > 2.5 on its right
  cut.v = {2.0, 0.5, 1.5, 1.0};
  PlanePolygon triangle{
      {p.plane, 1},
      {{p.set.add(cut), -1}, {p.set.add_axis(0, 2.0), 1}, {p.set.add_axis(1, 1.0), 1}},
      {}};
  for (std::size_t m = 0; m < 3; ++m)
    triangle.vertices.push_back(
        make_point(p.set, p.plane, triangle.lines[m].id, triangle.lines[(m + 1) % 3].id));
  EXPECT_FALSE(interiors_meet(p.set, mitred, triangle));
  // Apart across the cut line only (no line of the rectangle parts them), either way round.
  const PlanePolygon cut_square = p.corner_cut(0, 0, 2, 2, 1, 0).polygon;
  EXPECT_FALSE(interiors_meet(p.set, cut_square, p.rectangle(1.6, 1.6, 3, 3)));
  EXPECT_FALSE(interiors_meet(p.set, p.rectangle(1.6, 1.6, 3, 3), cut_square));
  EXPECT_TRUE(interiors_meet(p.set, p.rectangle(1.4, 1.4, 3, 3), cut_square));
  EXPECT_TRUE(interiors_meet(p.set, mitred, p.rectangle(1.9, 0.4, 2.5, 1.5)));
}

TEST(LoneFaces, ALoneFaceLooksOutwardWithItsEdgesOnTheirLines) {
  AxisPlane p(2);
  for (const bool below : {true, false}) {
    SCOPED_TRACE(below);
    std::vector<Contribution> contributions{
        {p.corner_cut(0, 0, 2, 1, 0.5, 3).polygon, 3, true, !below, below}};
    const std::vector<SolidFace> faces = take_lone_faces(p.set, {p.plane, 1}, contributions);
    EXPECT_TRUE(contributions.empty());
    ASSERT_EQ(faces.size(), 1u);
    const SolidFace& f = faces[0];
    EXPECT_EQ(f.owner, 3u);
    EXPECT_EQ(f.plane, (PlaneRef{p.plane, below ? 1 : -1}));
    ASSERT_EQ(f.vertices.size(), 5u);
    ASSERT_EQ(f.lines.size(), 5u);
    EXPECT_DOUBLE_EQ(twice_area_outside(f, p.i, p.j), 2 * (2.0 - 0.125));
    for (std::size_t k = 0; k < 5; ++k) {  // edge k runs from vertex k to vertex k + 1 on lines[k]
      EXPECT_EQ(side(p.set, f.lines[k], f.vertices[k]), 0) << k;
      EXPECT_EQ(side(p.set, f.lines[k], f.vertices[(k + 1) % 5]), 0) << k;
    }
  }
}

TEST(LoneFaces, SectionsAndHolesAloneAreNoFacesAndOverlapsStay) {
  AxisPlane p(2);
  Contribution hole_face = p.face_below(10, 10, 11, 11, 4);
  hole_face.solid = false;
  std::vector<Contribution> contributions{
      p.face_below(0, 0, 1, 1, 0),                     // lone: a face
      {p.rectangle(1, 0, 2, 1), 1, true, true, true},  // lone (touching the first): no face
      p.hole_section(5, 5, 6, 6, 2),                   // lone: no face
      hole_face,                                       // lone: no face
      p.face_below(3, 0, 4, 1, 5),                     // these two overlap: they stay
      p.hole_section(3.5, 0.5, 4.5, 1.5, 6)};
  const std::vector<SolidFace> faces = take_lone_faces(p.set, {p.plane, 1}, contributions);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].owner, 0u);
  ASSERT_EQ(contributions.size(), 2u);
  EXPECT_EQ(contributions[0].primitive, 5u);
  EXPECT_EQ(contributions[1].primitive, 6u);
}

TEST(LoneFaces, WithTheBooleanOfTheRestTheyCoverWhatTheBooleanOfAllCovers) {
  // Rectangles and corner-cut rectangles on a 6 x 6 lattice, most touching, some
  // overlapping: faces below and above, solid and hole sections, holes' faces.
  std::mt19937_64 random(20261202);
  int lone_cases = 0;
  for (int c = 0; c < 300; ++c) {
    SCOPED_TRACE(c);
    AxisPlane p(2);
    std::vector<Contribution> contributions;
    const int n = 1 + int(random() % 6);
    for (int m = 0; m < n; ++m) {
      const int a0 = int(random() % 6), b0 = int(random() % 6);
      const int a1 = a0 + 1 + int(random() % 2), b1 = b0 + 1 + int(random() % 2);
      const int kind =
          int(random() % 5);  // face below, face above, solid section, hole section, hole face
      const std::size_t owner = random() % 4;
      PlanePolygon polygon = random() % 3 == 0 ? p.corner_cut(a0, b0, a1, b1, 0.5, owner).polygon
                                               : p.rectangle(a0, b0, a1, b1);
      contributions.push_back(
          {std::move(polygon), owner, kind != 3 && kind != 4, kind != 0, kind != 1 && kind != 4});
    }
    const PlaneFaces all = PlaneBoolean(p.set, {p.plane, 1}, contributions).faces();
    if (!all.holes.empty()) continue;  // a ring: cuts would split the faces, not the areas
    std::vector<SolidFace> faces = take_lone_faces(p.set, {p.plane, 1}, contributions);
    lone_cases += !faces.empty();
    if (!contributions.empty()) {
      const PlaneFaces rest = PlaneBoolean(p.set, {p.plane, 1}, contributions).faces();
      ASSERT_TRUE(rest.holes.empty());
      faces.insert(faces.end(), rest.faces.begin(), rest.faces.end());
    }
    const auto expected = areas(all.faces, p.i, p.j);
    const auto got = areas(faces, p.i, p.j);
    ASSERT_EQ(got.size(), expected.size());
    for (const auto& [key, area] : expected) EXPECT_NEAR(got.at(key), area, 1e-12);
  }
  EXPECT_GT(lone_cases, 100);  // the cases exercise the shortcut
}

}  // namespace
}  // namespace roomcad::detail
