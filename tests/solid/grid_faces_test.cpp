// SPDX-License-Identifier: GPL-3.0-or-later
// grid_faces (detail/grid_faces.h): the faces of a plane of rectangles from the grid of their
// lines. Each face must be a simple polygon looking outward, and each owner's faces must cover
// exactly the cells the rule of Presence gives it: checked cell by cell against a brute-force
// classification of random rectangles, and against the general boolean (PlaneBoolean) on the
// same rectangles.
#include "solid/detail/general_path/grid_faces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "axis_plane.h"

namespace roomcad::detail {
namespace {

// Each face: simple (no corner twice), of positive area seen from outside, its edges along the
// axes where no slanted polygon is near.
void expect_simple_outward(const std::vector<SolidFace>& faces, int i, int j,
                           bool along_axes = true) {
  for (const SolidFace& f : faces) {
    ASSERT_GE(f.rounded.size(), along_axes ? 4u : 3u);
    ASSERT_EQ(f.vertices.size(), f.rounded.size());
    ASSERT_EQ(f.lines.size(), f.rounded.size());
    std::set<std::array<double, 3>> corners(f.rounded.begin(), f.rounded.end());
    EXPECT_EQ(corners.size(), f.rounded.size()) << "a corner twice";
    for (std::size_t m = 0; m < f.rounded.size(); ++m) {
      const auto& p = f.rounded[m];
      const auto& q = f.rounded[(m + 1) % f.rounded.size()];
      EXPECT_TRUE(!along_axes || p[std::size_t(i)] == q[std::size_t(i)] ||
                  p[std::size_t(j)] == q[std::size_t(j)]);
    }
    EXPECT_GT(twice_area_outside(f, i, j), 0.0);
  }
}

// A random box of whole cells on the 6 x 6 lattice: [a0, a1] x [b0, b1], never empty.
struct CellBox {
  int a0, b0, a1, b1;
};
CellBox random_cell_box(std::mt19937_64& random) {
  const int a0 = int(random() % 6), b0 = int(random() % 6);
  return {a0, b0, a0 + 1 + int(random() % (6 - a0)), b0 + 1 + int(random() % (6 - b0))};
}

TEST(GridFaces, AWallFaceWithAWindowIsSimpleFacesAroundIt) {
  AxisPlane p(0);  // a wall's side x = 0, the wall behind it
  const auto faces =
      grid_faces(p.set, {p.plane, 1}, {p.face_below(0, 0, 4, 2.5), p.hole_section(1, 1, 2, 2, 1)});
  ASSERT_TRUE(faces.has_value());
  expect_simple_outward(*faces, p.i, p.j);
  // Cut through the window's top: the part below it around the window, and the part above.
  EXPECT_EQ(faces->size(), 2u);
  const auto a = areas(*faces, p.i, p.j);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_DOUBLE_EQ(a.at({1, 0}), 4 * 2.5 - 1.0);
}

TEST(GridFaces, CellsTouchingAtACornerOnlyAreSeparateFaces) {
  AxisPlane p(2);
  const auto faces =
      grid_faces(p.set, {p.plane, 1}, {p.face_below(0, 0, 1, 1), p.face_below(1, 1, 2, 2)});
  ASSERT_TRUE(faces.has_value());
  expect_simple_outward(*faces, p.i, p.j);
  ASSERT_EQ(faces->size(), 2u);
  for (const SolidFace& f : *faces) EXPECT_EQ(f.vertices.size(), 4u);
}

TEST(GridFaces, ARingTouchingItselfAtACornerIsCutIntoSimpleFaces) {
  // A frame of four strips around (1, 1)-(2, 2) whose corner (2, 2) is left out but for its
  // two neighbours touching there: the hole inside reaches the outside at that point only.
  AxisPlane p(1);
  std::vector<Contribution> ring{p.face_below(0, 0, 3, 1), p.face_below(0, 1, 1, 3),
                                 p.face_below(1, 2, 2, 3), p.face_below(2, 1, 3, 2)};
  const auto faces = grid_faces(p.set, {p.plane, 1}, ring);
  ASSERT_TRUE(faces.has_value());
  expect_simple_outward(*faces, p.i, p.j);
  double total = 0.0;
  for (const auto& [key, area] : areas(*faces, p.i, p.j)) total += area;
  EXPECT_DOUBLE_EQ(total, 3.0 + 2.0 + 1.0 + 1.0);
}

TEST(GridFaces, FacesLookOutwardOnAPlaneWhoseNormalPointsDown) {
  // The plane x = 0 given with its normal along -x (through two plan points): faces on its
  // positive side look along -x, and must be counter-clockwise seen from there.
  PlaneSet set;
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::through2;
  r.v = {0.0, 1.0, 0.0, 0.0};  // from (0, 1) to (0, 0): normal (-1, 0, 0)
  const PlaneId plane = set.add(r);
  // The rectangle 0 <= y <= 2, 0 <= z <= 1 (grid_faces reads only its lines).
  const PlaneRef lines[4] = {{set.add_axis(1, 0.0), -1},
                             {set.add_axis(2, 0.0), -1},
                             {set.add_axis(1, 2.0), 1},
                             {set.add_axis(2, 1.0), 1}};
  PlanePolygon poly{{plane, 1}, {lines, lines + 4}, {}};
  for (std::size_t m = 0; m < 4; ++m)
    poly.vertices.push_back(make_point(set, plane, lines[m].id, lines[(m + 1) % 4].id));
  for (const bool below : {true, false}) {
    const auto faces = grid_faces(set, {plane, 1}, {{poly, 0, true, !below, below}});
    ASSERT_TRUE(faces.has_value());
    ASSERT_EQ(faces->size(), 1u);
    const SolidFace& f = faces->front();
    EXPECT_EQ(f.plane.sign, below ? 1 : -1);
    // Seen from outside, along sign * (-x): counter-clockwise in (y, z) seen from -x is
    // clockwise seen from +x.
    double sum = 0.0;
    for (std::size_t m = 0; m < 4; ++m) {
      const auto& a = f.rounded[m];
      const auto& b = f.rounded[(m + 1) % 4];
      sum += a[1] * b[2] - b[1] * a[2];
    }
    EXPECT_LT(sum * f.plane.sign, 0.0) << "seen from +x, a face looking along -x turns clockwise";
  }
}

TEST(GridFaces, APlaneOfMostlySlantedPolygonsIsLeftToTheGeneralBoolean) {
  AxisPlane p(2);
  EXPECT_FALSE(grid_faces(p.set, {p.plane, 1},
                          {p.corner_cut(0, 0, 2, 2, 1, 0), p.corner_cut(1, 1, 3, 3, 1, 1)})
                   .has_value());
}

TEST(GridFaces, APlaneOfMoreCellsThanTheGridTakesIsLeftToTheGeneralBoolean) {
  // A staircase of thin rectangles, each of its own lines: n lines a family, (n - 1)^2 cells.
  const auto staircase = [](AxisPlane& p, int steps) {
    std::vector<Contribution> out;
    for (int m = 0; m < steps; ++m) out.push_back(p.face_below(m, m, m + 0.5, m + 0.5, 0));
    return out;
  };
  AxisPlane small(2), large(2);
  const int fits = 256, too_many = 300;  // 511^2 < kMaxGridCells < 599^2
  ASSERT_LT(std::size_t(2 * fits - 1) * (2 * fits - 1), kMaxGridCells);
  ASSERT_GT(std::size_t(2 * too_many - 1) * (2 * too_many - 1), kMaxGridCells);
  EXPECT_TRUE(grid_faces(small.set, {small.plane, 1}, staircase(small, fits)).has_value());
  EXPECT_FALSE(grid_faces(large.set, {large.plane, 1}, staircase(large, too_many)).has_value());
}

TEST(GridFaces, AWallTopMitredAtACornerGetsTheFacesOfTheGeneralBoolean) {
  // A wall's top whose end is mitred (a corner cut at 45 degrees), the top of a wall beside the
  // mitre, another's apart, and the section of a wall across them: the cells the mitre may
  // cross go to the general boolean, the rest to the grid.
  AxisPlane p(2);
  const std::vector<Contribution> tops{p.corner_cut(0, 0, 4, 1, 0.5, 0),
                                       p.face_below(3, 1, 4, 3, 1),
                                       p.face_below(2, 2, 3, 4, 2),
                                       {p.rectangle(1, 0, 2, 3), 3, true, true, true}};
  const auto faces = grid_faces(p.set, {p.plane, 1}, tops);
  ASSERT_TRUE(faces.has_value());
  expect_simple_outward(*faces, p.i, p.j, false);
  const PlaneFaces general = PlaneBoolean(p.set, {p.plane, 1}, tops).faces();
  ASSERT_TRUE(general.holes.empty());
  EXPECT_EQ(areas(*faces, p.i, p.j), areas(general.faces, p.i, p.j));
}

TEST(GridFaces, RandomRectanglesGetTheOwnersOfEveryCellAsTheGeneralBooleanDoes) {
  // Rectangles on a 6 x 6 lattice of unit cells: faces (solid below or above), solid and hole
  // sections; every cell centre lies inside or outside each rectangle, never on an edge.
  std::mt19937_64 random(20261201);
  int compared_with_boolean = 0;
  constexpr int kCases = 400;
  for (int c = 0; c < kCases; ++c) {
    SCOPED_TRACE(c);
    AxisPlane p(int(c % 3));
    std::vector<Contribution> contributions;
    const int n = 1 + int(random() % 7);
    for (int m = 0; m < n; ++m) {
      const auto [a0, b0, a1, b1] = random_cell_box(random);
      // face below, face above, solid section, hole section, hole face
      const int kind = int(random() % 5);
      Contribution x{p.rectangle(a0, b0, a1, b1), std::size_t(random() % 4), kind != 3 && kind != 4,
                     kind != 0, kind != 1 && kind != 4};
      contributions.push_back(x);
    }
    const auto faces = grid_faces(p.set, {p.plane, 1}, contributions);
    ASSERT_TRUE(faces.has_value());
    expect_simple_outward(*faces, p.i, p.j);
    // Brute force: each unit cell's owners from the rectangles holding its centre.
    std::map<std::pair<int, std::size_t>, double> expected;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        Presence at;
        for (const Contribution& x : contributions) {
          const auto lo_i = x.polygon.vertices[0].approx[std::size_t(p.i)].inf();
          const auto lo_j = x.polygon.vertices[0].approx[std::size_t(p.j)].inf();
          const auto hi_i = x.polygon.vertices[2].approx[std::size_t(p.i)].inf();
          const auto hi_j = x.polygon.vertices[2].approx[std::size_t(p.j)].inf();
          if (a + 0.5 > lo_i && a + 0.5 < hi_i && b + 0.5 > lo_j && b + 0.5 < hi_j) at.add(x);
        }
        const FaceOwners o = at.owners();
        if (o.up >= 0) expected[{1, std::size_t(o.up)}] += 1.0;
        if (o.down >= 0) expected[{-1, std::size_t(o.down)}] += 1.0;
      }
    EXPECT_EQ(areas(*faces, p.i, p.j), expected);
    PlaneBoolean boolean(p.set, {p.plane, 1}, contributions);
    const PlaneFaces general = boolean.faces();
    // Compared where the boolean has no face with a hole (those need cuts first,
    // general_solid.cpp).
    if (general.holes.empty()) {
      ++compared_with_boolean;
      EXPECT_EQ(areas(general.faces, p.i, p.j), expected);
    }
  }
  EXPECT_GT(compared_with_boolean, kCases / 2);
}

TEST(GridFaces, RandomRectanglesAndMitresGetTheFacesOfTheGeneralBoolean) {
  // As above on z = 0, a third of the polygons with a corner cut at 45 degrees (a mitre): the
  // windows around the cuts go to the general boolean, the rest to the grid. Every corner lies
  // on a half-unit lattice, so the areas are exact.
  std::mt19937_64 random(20261202);
  int compared = 0;
  constexpr int kCases = 300;
  for (int c = 0; c < kCases; ++c) {
    SCOPED_TRACE(c);
    AxisPlane p(2);
    std::vector<Contribution> contributions;
    const int n = 2 + int(random() % 6);
    for (int m = 0; m < n; ++m) {
      const auto [a0, b0, a1, b1] = random_cell_box(random);
      const int kind = int(random() % 4);  // face below, face above, solid section, hole section
      const double cut =
          std::min(a1 - a0, b1 - b0) > 1 && random() % 2 ? 1.0 : 0.5;  // shorter than a side
      Contribution x =
          m % 3 == 0 ? p.corner_cut(a0, b0, a1, b1, cut, 0) : p.face_below(a0, b0, a1, b1);
      x.primitive = std::size_t(random() % 4);
      x.solid = kind != 3, x.above = kind != 0, x.below = kind != 1;
      contributions.push_back(std::move(x));
    }
    const auto faces = grid_faces(p.set, {p.plane, 1}, contributions);
    const PlaneFaces general = PlaneBoolean(p.set, {p.plane, 1}, contributions).faces();
    if (!faces || !general.holes.empty()) continue;
    ++compared;
    expect_simple_outward(*faces, p.i, p.j, false);
    EXPECT_EQ(areas(*faces, p.i, p.j), areas(general.faces, p.i, p.j));
  }
  EXPECT_GT(compared, kCases / 3);
}

}  // namespace
}  // namespace roomcad::detail
