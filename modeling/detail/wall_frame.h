// Each wall in its own frame (u along from -> to, w to the left, z up) with its holes, the
// common input of every builder (fast path, CGAL path, analytic volume, fixtures).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "modeling/joins.h"
#include "modeling/plan.h"

namespace roomcad::detail {

/// An opening's hole in its wall's frame: u in [u0, u1] along the wall, z in [z0, z1]
/// absolute (base + sill ...), through the full thickness.
struct Hole {
  std::size_t opening = 0;  ///< index into Plan::openings
  double u0 = 0.0, u1 = 0.0, z0 = 0.0, z1 = 0.0;
};

/// Where the end of another wall (a stem) is glued to one side face of this wall: that side
/// has no face over u in [u0, u1] (full height), and its corners there are p0 and p1 exactly.
struct Attachment {
  double u0 = 0.0, u1 = 0.0;
  int side = 1;  ///< -1 right face, +1 left face
  Point2 p0, p1;
};

struct WallFrame {
  std::size_t wall = 0;  ///< index into Plan::walls
  Point2 from;
  Point2 to;
  Point2 dir;     ///< unit vector from -> to (rounded)
  Point2 normal;  ///< dir turned left by 90 degrees (exactly, from the rounded dir)
  double length = 0.0;
  double half = 0.0;  ///< half the thickness
  double base = 0.0;
  double top = 0.0;
  std::array<Point2, 4> footprint;  ///< wall_footprint: from-right, to-right, to-left, from-left
  std::array<bool, 2> capless{false, false};  ///< per WallEnd: no end cap (mitred, or on a hub)
  Color color;
  std::vector<Hole> holes;  ///< sorted by u0
  std::vector<Attachment> attachments;  ///< stems glued to its sides (fast path only)
};

/// Frames for every wall, with the holes of every opening. Ends are mitred per `joins`, and
/// also where two walls of equal thickness among three or more at one node run on from each
/// other within 1e-6 rad (a hairline wedge between square ends; see wall_frame.cpp).
/// @pre validate(plan).ok() for the checks below (validation/validate.h).
/// @return one frame per wall, in plan order. O(n log n).
/// @throws PreconditionError naming the wall or opening if a wall is degenerate (length,
///         thickness or height not positive and finite) or an opening cannot be cut (unknown
///         wall, empty, or not inside [0, length] x [0, height] of its wall).
[[nodiscard]] std::vector<WallFrame> make_wall_frames(const Plan& plan, const Joins& joins);

/// @return the point at u along the wall on its right (side = -1) or left (side = +1) face,
///         rounded to doubles. O(1).
[[nodiscard]] Point2 side_point(const WallFrame& frame, double u, int side);

/// @return the index into Model::objects of an opening (walls come first).
[[nodiscard]] inline int opening_object(const Plan& plan, std::size_t opening) {
  return static_cast<int>(plan.walls.size() + opening);
}

}  // namespace roomcad::detail
