// SPDX-License-Identifier: GPL-3.0-or-later
// Slabs built with the walls (docs/plan-format.md "Version 2", slab_frames.h, slab_edges.h):
// one closed solid, the holes of the slab's area kept, a floor drawn to the walls' faces laid
// into them, the faces named after the slab.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "solid/detail/frames/slab_frames.h"
#include "support/model_support.h"

namespace roomcad {
namespace {

using test::add_room;
using test::add_wall;
using test::empty_plan;
using test::expect_valid_walls;

// A 5 x 4 room (walls 0.2 thick, 2.7 high, mitred) under a slab 0.2 thick whose top is the
// walls' top: the outline 5.2 x 4.2 covers the walls, a stair well 1 x 2 inside.
Plan covered_room() {
  Plan plan = empty_plan();
  add_room(plan, "r", 1, 1, 5, 4);
  for (Wall& w : plan.walls) w.height = 2.7;
  Slab s;
  s.id = "lid";
  s.outline = {{0.9, 0.9}, {6.1, 0.9}, {6.1, 5.1}, {0.9, 5.1}};
  s.holes = {{{2, 2}, {3, 2}, {3, 4}, {2, 4}}};
  s.top = 2.7, s.thickness = 0.2;
  plan.slabs.push_back(s);
  return plan;
}

TEST(SlabBuild, ASlabAndTheWallsItMeetsAreOneClosedSolid) {
  // Walls: 0.2 x 18 (centre line) x 2.7 = 9.72; slab: (5.2 x 4.2 - 1 x 2) x 0.2 = 3.968; the
  // slab's bottom 0.2 over the walls' plan area (3.6 m^2) is counted once: - 0.72.
  // A lid with a stair well: genus 1 (the ring of walls is closed by the lid).
  for (const BooleanPath path : {BooleanPath::automatic, BooleanPath::general})
    expect_valid_walls(covered_room(), path, 1, 9.72 + 3.968 - 0.72);
}

TEST(SlabBuild, FacesOfTheSlabNameItAfterTheWallsAndOpenings) {
  const Model model = build_model(covered_room());
  ASSERT_EQ(model.objects.size(), 5u);
  EXPECT_EQ(model.objects[4], "lid");
  const FacePropertyHandles props = face_property_handles(model.walls);
  std::set<int> slab_objects;
  for (const auto f : model.walls.faces())
    if (model.walls.property(props.kind, f) == FaceKind::slab)
      slab_objects.insert(model.walls.property(props.object, f));
  EXPECT_EQ(slab_objects, std::set<int>{4});
}

TEST(SlabBuild, AFloorDrawnToTheWallsFacesIsLaidIntoThemNotLeftOnASliver) {
  // An upper storey's walls reach down through its floor (as Sweet Home 3D draws them), the
  // floor drawn to their inner faces at x = 3.2872205 + 0.13, which no double holds: within
  // rounding of the side, a sliver away from it. Laid into the walls, the floor joins them
  // face to face: the walls (0.26 x 4 x 2.74 each, 4 x 3 centre-line room, mitred: 0.26 x 14
  // x 2.74) and the floor inside them ((4 - 0.26) x (3 - 0.26) x 0.12) make one solid.
  Plan plan = empty_plan();
  add_room(plan, "u", 3.2872205, 1, 4, 3);
  for (Wall& w : plan.walls) w.thickness = 0.26, w.base = 2.5, w.height = 2.74;
  const double x0 = 3.2872205 + 0.13, x1 = 3.2872205 + 4 - 0.13;
  Slab s;
  s.id = "floor";
  s.outline = {{x0, 1.13}, {x1, 1.13}, {x1, 3.87}, {x0, 3.87}};
  s.top = 2.62, s.thickness = 0.12;
  plan.slabs.push_back(s);
  expect_valid_walls(plan, BooleanPath::automatic, 0,
                     0.26 * 14 * 2.74 + (4 - 0.26) * (3 - 0.26) * 0.12);
}

TEST(SlabBuild, AFloorBesideAWallStandingOnItsEdgeIsLaidUnderIt) {
  // A wall (x = 4.4 +- 0.2175, from z = 1.25) stands where a floor 0.127 thick ends, its side
  // at 4.4 + 0.2175, the floor drawn to 4.6175: they would share a bare edge (duplex.ifc).
  // Laid a quarter thickness under the wall, the floor joins it face to face; the solid
  // gains the strip (0.435 / 4 x 2 x 0.127).
  Plan plan = empty_plan();
  add_wall(plan, "w", {4.4, 0}, {4.4, 2});
  Wall& w = plan.walls[0];
  w.thickness = 0.435, w.base = 1.25, w.height = 1;
  Slab s;
  s.id = "floor";
  s.outline = {{4.6175, 0}, {7, 0}, {7, 2}, {4.6175, 2}};
  s.top = 1.25, s.thickness = 0.127;
  plan.slabs.push_back(s);
  const double strip = 0.435 / 4 * 2 * 0.127;
  expect_valid_walls(plan, BooleanPath::automatic, 0,
                     0.435 * 2 * 1 + (7 - 4.6175) * 2 * 0.127 + strip);
}

TEST(SlabBuild, AFloorAlongAWallEndAndAWallUnderItIsLaidWhole) {
  // From duplex.ifc: wall a ends at x = 4.6175 (its end face), wall b below the floor has its
  // side at 4.4 + 0.2175 (a double above 4.6175) and its top at the floor's bottom; the
  // floor's edge at 4.6175 runs along both and on past them. As drawn, the solid pinches at a
  // point where a, b and the floor meet (two empty corners touch there). The edge moves whole,
  // a quarter of a's thickness into a and over b, and the solid is 2-manifold.
  Plan plan = empty_plan();
  add_wall(plan, "a", {0.417, -10}, {4.6175, -10});
  add_wall(plan, "b", {4.4, -9.7825}, {4.4, -8.0175});
  for (Wall& w : plan.walls) w.thickness = 0.435, w.height = 1.25;
  plan.walls[1].height = 1.123;
  Slab s;
  s.id = "floor";
  s.outline = {{4.6175, -8.075}, {4.6175, -10.275}, {6, -10.275}, {6, -8.075}};
  s.top = 1.25, s.thickness = 0.127;
  plan.slabs.push_back(s);
  const double laid = 4.6175 - 0.435 / 4;
  // a + b + the laid floor, less the floor's part inside a (x from laid to 4.6175, a's y).
  const double volume = 4.2005 * 0.435 * 1.25 + 1.765 * 0.435 * 1.123 + (6 - laid) * 2.2 * 0.127 -
                        (4.6175 - laid) * 0.435 * 0.127;
  expect_valid_walls(plan, BooleanPath::automatic, 0, volume);
}

TEST(SlabBuild, AnOutlineThatCrossesItselfIsRefusedNamingTheSlab) {
  Plan plan = covered_room();
  plan.slabs[0].outline = {{0.9, 0.9}, {6.1, 5.1}, {6.1, 0.9}, {0.9, 5.1}};  // a bow tie
  test::expect_build_refused(plan, {}, Code::not_buildable, "slab 'lid'");
}

// A slab whose every edge runs along x or y is cut into rectangles between its own
// coordinates; any other into the triangulation's convex pieces of its own corners. Either way
// the pieces cover its area once.
TEST(SlabBuild, ARectilinearAreaIsCutIntoRectanglesOfItsOwnCoordinates) {
  Plan plan = empty_plan();
  Slab s;
  s.id = "floor";
  s.outline = {{0, 0}, {6, 0}, {6, 2}, {3, 2}, {3, 5}, {0, 5}};  // an L
  s.holes = {{{1, 1}, {2, 1}, {2, 3}, {1, 3}}, {{4, 0.5}, {5, 0.5}, {5, 1.5}, {4, 1.5}}};
  s.top = 0.2, s.thickness = 0.2;
  plan.slabs.push_back(s);
  const auto area = [](const Polygon& p) {
    double a = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k)
      a += p[k].x * p[(k + 1) % p.size()].y - p[(k + 1) % p.size()].x * p[k].y;
    return a / 2.0;
  };
  const std::set<double> xs{0, 1, 2, 3, 4, 5, 6}, ys{0, 0.5, 1, 1.5, 2, 3, 5};
  const std::vector<detail::SlabFrame> frames = detail::make_slab_frames(plan, {});
  ASSERT_EQ(frames.size(), 1u);
  double total = 0.0;
  for (const Polygon& piece : frames[0].pieces) {
    ASSERT_EQ(piece.size(), 4u);
    EXPECT_GT(area(piece), 0.0) << "counter-clockwise";
    for (std::size_t k = 0; k < 4; ++k) {
      const Point2 a = piece[k], b = piece[(k + 1) % 4];
      EXPECT_TRUE(a.x == b.x || a.y == b.y);
      EXPECT_TRUE(xs.count(a.x) && ys.count(a.y)) << a.x << ", " << a.y;
    }
    total += area(piece);
  }
  EXPECT_DOUBLE_EQ(total, 6 * 2 + 3 * 3 - 2 - 1);
  // Its volume on the general path, whatever the pieces.
  expect_valid_walls(plan, BooleanPath::automatic, 2, (6 * 2 + 3 * 3 - 2 - 1) * 0.2);
  plan.slabs[0].outline[3].x = 3.5;  // the L's inner corner pulled askew: a slanted edge
  const Slab& askew = plan.slabs[0];
  const auto is_own_corner = [&](const Point2& p) {
    const auto in = [&](const Polygon& ring) {
      return std::find(ring.begin(), ring.end(), p) != ring.end();
    };
    return in(askew.outline) || std::any_of(askew.holes.begin(), askew.holes.end(), in);
  };
  const std::vector<detail::SlabFrame> triangulated = detail::make_slab_frames(plan, {});
  ASSERT_EQ(triangulated.size(), 1u);
  for (const Polygon& piece : triangulated[0].pieces)
    for (const Point2& p : piece) EXPECT_TRUE(is_own_corner(p)) << p.x << ", " << p.y;
}

TEST(SlabBuild, TheNefPathRefusesSlabsByName) {
  test::expect_build_refused(covered_room(), test::options_for(BooleanPath::nef),
                             Code::not_buildable, "slab 'lid'");
}

}  // namespace
}  // namespace roomcad
