// SPDX-License-Identifier: GPL-3.0-or-later
// Numerical stress for the wall solid: a room and a free wall with openings flush with wall
// ends, mitred corners and wall tops (openings always go through the whole thickness), and
// walls of equal height side by side; walls 0.25 m and 2^-13 m (1.2e-4 m) thick, built 1e6
// and 1e7 m from the origin and turned by 1e-9, 45 and 89.9999999 degrees, on the fast and
// the CGAL path: closed, manifold, outward, the analytic volume.
//
// Every plan here validates without errors. Flush with a mitred corner and touching side by
// side are exact only where the numbers are: dyadic sizes, axis-aligned, moved by whole metres;
// turned, they would overlap or gap by an ulp, which validation reports.
// Volumes are compared within volume_tolerance (solid/wall_check.h): 1e-9 relative,
// plus what rounding the output vertices to doubles allows (an ulp of 1e7 m is 1.9e-9 m).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/model_support.h"

namespace roomcad {
namespace {

using test::add_opening;
using test::add_room;
using test::add_wall;
using test::empty_plan;
using test::kDoor;
using test::kWindow;

/// A 5 x 4 room of walls `t` thick: a door, a window inside a wall, a window flush with the
/// inner face of the mitred corner, a window reaching the top; and a free 3 m wall with a door
/// flush with one end and a window flush with the other end and the top. Genus 3 (the ring
/// and two window tunnels), two components. `t` dyadic, so that the corner window is flush.
Plan flush_openings_plan(double t) {
  Plan plan = empty_plan();
  add_room(plan, "r", 0, 0, 5, 4);
  add_wall(plan, "free", {7, 0}, {10, 0});
  for (Wall& w : plan.walls) w.thickness = t;
  add_opening(plan, "door", kDoor, "r0", 1.0, 0.9, 0.0, 2.1);
  add_opening(plan, "inside", kWindow, "r1", 1.0, 1.2, 0.9, 1.2);
  add_opening(plan, "corner", kWindow, "r2", 5 - t / 2 - 1.0, 1.0, 0.9, 1.0);
  add_opening(plan, "top", kWindow, "r3", 1.0, 1.0, 1.5, 1.0);
  add_opening(plan, "end-door", kDoor, "free", 0.0, 0.9, 0.0, 2.1);
  add_opening(plan, "end-top", kWindow, "free", 2.0, 1.0, 1.5, 1.0);
  return plan;
}

double flush_openings_volume(double t) {
  const double room = 2 * t * (5 + 4) * 2.5, free = 3 * t * 2.5;
  const double holes = 0.9 * 2.1 + 1.2 * 1.2 + 1.0 * 1.0 + 1.0 * 1.0 + 0.9 * 2.1 + 1.0 * 1.0;
  return room + free - t * holes;
}

struct Placement {
  double degrees;
  double dx, dy;
};

/// Turned, and moved up to 1e7 m: where flush and touching are not exact.
std::vector<Placement> turned_placements() {
  std::vector<Placement> out;
  for (const double d : {0.0, 1e6, 1e7})
    for (const double degrees : {1e-9, 45.0, 89.9999999}) out.push_back({degrees, d, -d});
  return out;
}

/// Axis-aligned, moved by whole metres: the dyadic numbers here stay exact up to 1e7 m.
std::vector<Placement> exact_placements() {
  return {{0.0, 0.0, 0.0}, {0.0, 1e6, -1e6}, {0.0, 1e7, -1e7}};
}

constexpr double kThicknesses[] = {0.25, 0x1p-13};

TEST(NumericalStress, FlushOpeningsAxisAlignedFarAwayHaveTheirExactVolume) {
  for (const double t : kThicknesses)
    for (const Placement& p : exact_placements()) {
      SCOPED_TRACE(fmt::format("walls {} m thick, moved ({}, {})", t, p.dx, p.dy));
      test::expect_paths_agree(test::transformed(flush_openings_plan(t), 0.0, p.dx, p.dy), 3,
                               flush_openings_volume(t));
    }
}

TEST(NumericalStress, FlushOpeningsTurnedAndFarAwayAreClosedWithTheAnalyticVolume) {
  for (const double t : kThicknesses)
    for (const Placement& p : turned_placements()) {
      SCOPED_TRACE(
          fmt::format("walls {} m thick, turned {} deg, moved ({}, {})", t, p.degrees, p.dx, p.dy));
      // Flush with a far end is not exact once turned (the length is a square root).
      Plan plan = flush_openings_plan(t);
      std::erase_if(plan.openings,
                    [](const Opening& o) { return o.id == "corner" || o.id == "end-top"; });
      test::expect_paths_agree(test::transformed(plan, p.degrees, p.dx, p.dy), 2);
    }
}

/// Two walls of equal height side by side, their footprints touching along a whole side
/// (not joined: their centre lines are a thickness apart).
Plan side_by_side_plan() {
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {3, 0});
  add_wall(plan, "b", {0, 0.25}, {3, 0.25});
  for (Wall& w : plan.walls) w.thickness = 0.25;
  return plan;
}

TEST(NumericalStress, WallsOfEqualHeightSideBySide) {
  for (const Placement& p : exact_placements()) {
    SCOPED_TRACE(fmt::format("moved ({}, {})", p.dx, p.dy));
    test::expect_paths_agree(test::transformed(side_by_side_plan(), 0.0, p.dx, p.dy), 0,
                             2 * 3 * 0.25 * 2.5);
  }
}

}  // namespace
}  // namespace roomcad
