// SPDX-License-Identifier: GPL-3.0-or-later
// Each wall in its own frame (u along from -> to, w to the left, z up) with its holes, the
// common input of every builder (fast path, CGAL path, analytic volume, fixtures).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "geometry/broad_phase.h"
#include "geometry/joins.h"
#include "plan/plan.h"

namespace roomcad::detail {

/// An opening's hole in its wall's frame: u in [u0, u1] along the wall, z in [z0, z1]
/// absolute (base + sill ...), through the full thickness; a shaped opening's hole is its
/// outline within that rectangle.
struct Hole {
  std::size_t opening = 0;  ///< index into Plan::openings
  double u0 = 0.0, u1 = 0.0, z0 = 0.0, z1 = 0.0;
  double width = 0.0, height = 0.0;  ///< the opening's, as written: `shape` maps through them
  Polygon shape;  ///< the opening's shape (unit square, counter-clockwise); empty: the rectangle
  /// Per end (from, to): the hole runs on through the mitre there, to the mitre line (a piece
  /// of an opening across the chords of an arc wall, buildable_plan.h).
  std::array<bool, 2> through_mitre{false, false};
};

/// Where the end of another wall (a stem) is glued to one side face of this wall: that side
/// has no face over u in [u0, u1] from the wall's base up to `top` (the stem's top, at most
/// this wall's), and its corners there are p0 and p1 exactly.
struct Attachment {
  double u0 = 0.0, u1 = 0.0;
  int side = 1;  ///< -1 right face, +1 left face
  Point2 p0, p1;
  double top = 0.0;  ///< metres, absolute
};

struct WallFrame {
  std::size_t wall = 0;  ///< index into Plan::walls
  std::string id;        ///< the wall's id, for messages (an arc's chord: "a (chord 2 of 5)")
  Point2 from;
  Point2 to;
  Point2 dir;     ///< unit vector from -> to (rounded)
  Point2 normal;  ///< dir turned left by 90 degrees (exactly, from the rounded dir)
  double length = 0.0;
  double half = 0.0;  ///< half the thickness
  double base = 0.0;
  double top = 0.0;      ///< base + height: the top at `from` (of the whole wall, if flat)
  double top_end = 0.0;  ///< base + height_at_end: the top at `to`
  double top_max = 0.0;  ///< at least the highest top over the footprint (sloped: its corners)
  /// The smallest size the build resolves in this wall, metres: 64 units in the last place of
  /// its coordinates and of its top. A wall shorter, thinner or lower is refused; a hole
  /// edge nearer than this to the wall's end, base or flat top is flush with it.
  double resolution = 0.0;
  std::array<double, 2> heights{};  ///< height, height_at_end as written: the slope's exact rise
  std::array<Point2, 4> footprint;  ///< wall_footprint: from-right, to-right, to-left, from-left
  std::array<bool, 2> capless{false, false};  ///< per WallEnd: no end cap (mitred, or on a hub)
  Color color;
  std::vector<Hole> holes;              ///< sorted by u0
  std::vector<Attachment> attachments;  ///< stems glued to its sides (fast path only)
};

/// @return the smallest size the build resolves among numbers of magnitude up to m: 64 units
///         in the last place. The exact solid's corners are written as doubles; a wall
///         shorter, thinner or lower than this folds its faces onto each other when they are
///         rounded (a wall an ulp long makes a solid that crosses itself).
///         A hole narrower than this is cut: it rounds away or to a slit whose faces meet, as
///         its volume is below the rounding's. O(1).
[[nodiscard]] double resolvable_size(double m);

/// @return the z of a x b: positive when b turns left of a.
[[nodiscard]] inline double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }

/// @return the unit direction along the wall away from its end `end` (its rounded dir, or
///         the opposite). O(1).
inline Point2 outward(const WallFrame& f, WallEnd end) {
  return end == WallEnd::from ? f.dir : Point2{-f.dir.x, -f.dir.y};
}

/// @return the distance of p along the wall from its `from` end point (its rounded dir). O(1).
[[nodiscard]] inline double u_of(const WallFrame& f, const Point2& p) {
  return (p.x - f.from.x) * f.dir.x + (p.y - f.from.y) * f.dir.y;
}

/// @return whether a side of the footprint runs backwards: its corner at the from end lies
///         past its corner at the to end (a mitre or hub corner beyond the wall's other end,
///         on a wall shorter than its neighbour is thick). Such a footprint is a bow-tie,
///         which only the general path builds. O(1).
[[nodiscard]] inline bool has_crossed_footprint(const WallFrame& f) {
  return u_of(f, f.footprint[0]) > u_of(f, f.footprint[1]) ||
         u_of(f, f.footprint[3]) > u_of(f, f.footprint[2]);
}

/// @return the box of the wall's footprint grown by `margin` metres, tagged with its wall. O(1).
[[nodiscard]] Box2 footprint_box(const WallFrame& f, double margin = 0.0);

/// @return the box of the wall's footprint between its base and its highest top (space_box),
///         tagged with its wall. O(1).
[[nodiscard]] SpaceBox footprint_space_box(const WallFrame& f);

/// @return whether the wall's top is sloped (a plane through its two top ends). O(1).
[[nodiscard]] inline bool is_sloped(const WallFrame& f) { return f.heights[0] != f.heights[1]; }

/// @return whether the wall needs the general path: a sloped top or a shaped hole. O(holes).
[[nodiscard]] bool needs_general_path(const WallFrame& f);

/// @return whether the hole's footprint reaches the line of the footprint's end `end` (0: from,
///         1: to) rather than stopping square at u0 (u1): it reaches that end, and the end is
///         a square cap or the hole runs on through its mitre. O(1).
[[nodiscard]] inline bool hole_reaches_end_line(const WallFrame& f, const Hole& h, int end) {
  const bool at_end = end == 0 ? h.u0 <= 0.0 : h.u1 >= f.length;
  return at_end && (!f.capless[std::size_t(end)] || h.through_mitre[std::size_t(end)]);
}

/// Frames for every wall, with the holes of every opening. Ends are mitred per `joins`, and
/// also where two walls of equal thickness among three or more at one node run on from each
/// other within 1e-6 rad (a hairline wedge between square ends; see wall_frame.cpp).
/// @pre validate(plan).ok() for the checks below (validation/validate.h).
/// @return one frame per wall, in plan order. O(n log n).
/// @throws PreconditionError naming the wall or opening if a wall is degenerate (length,
///         thickness or height not positive and finite, or below its resolution) or an
///         opening cannot be cut (unknown wall, empty, or not inside [0, length] x [0, height]
///         of its wall to within its resolution).
/// @param through_mitre  per opening (or empty: none), whether its hole runs on through a
///                       mitre at its wall's from and to ends (Hole::through_mitre).
[[nodiscard]] std::vector<WallFrame> make_wall_frames(
    const Plan& plan, const Joins& joins, std::span<const std::array<bool, 2>> through_mitre = {});

/// @return the point at u along the wall on its right (side = -1) or left (side = +1) face,
///         rounded to doubles. O(1).
[[nodiscard]] Point2 side_point(const WallFrame& frame, double u, int side);

/// @return the index into Model::objects of an opening (walls come first).
[[nodiscard]] inline int opening_object(const Plan& plan, std::size_t opening) {
  return static_cast<int>(plan.walls.size() + opening);
}

/// @return the index into Model::objects of a slab (after the walls and the openings).
[[nodiscard]] inline int slab_object(const Plan& plan, std::size_t slab) {
  return static_cast<int>(plan.walls.size() + plan.openings.size() + slab);
}

}  // namespace roomcad::detail
