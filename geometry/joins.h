// SPDX-License-Identifier: GPL-3.0-or-later
// Where walls meet, after the spec's "Junctions" section.
//
// Two walls are joined where their centre lines meet: they cross, or an end point of one lies
// within `site.tolerance` of the other's centre line or end point. At an end point shared by
// exactly two walls (and touched by no third centre line) the two are mitred, unless the
// mitre would reach too far (kMitreReach); every other meeting (T, X, three or more walls)
// joins by union. Validation uses this to excuse joined
// walls from overlap errors; modeling uses it to shape the wall solids.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "plan/plan.h"

namespace roomcad {

enum class WallEnd : std::uint8_t { from = 0, to = 1 };

enum class JoinKind : std::uint8_t {
  mitre,  ///< an end point shared by exactly two walls: both footprints end on the mitre line
  unite,  ///< T, X or a meeting of three or more walls: the boxes are united as they are
};

/// One pair of joined walls (indices into Plan::walls, a < b).
struct Join {
  std::size_t a = 0;
  std::size_t b = 0;
  JoinKind kind = JoinKind::unite;
  Point2 point;  ///< where the centre lines meet (the shared end point for a mitre)
  friend bool operator==(const Join&, const Join&) = default;
};

struct Joins {
  std::vector<Join> pairs;  ///< sorted by (a, b), one entry per joined pair
  /// mitre[w][e]: the wall mitred to wall w at end e (index into Plan::walls), if any.
  std::vector<std::array<std::optional<std::size_t>, 2>> mitre;

  /// @return true if walls a and b are joined (either order). O(log n).
  [[nodiscard]] bool are_joined(std::size_t a, std::size_t b) const;
  /// @return the join of a and b (either order), or nullptr. O(log n).
  [[nodiscard]] const Join* find(std::size_t a, std::size_t b) const;
};

/// How far a mitre may reach: its corners lie within this many thicknesses (of the thicker
/// wall) of the shared end point, or the two walls join by union instead (see joins.cpp).
inline constexpr double kMitreReach = 4.0;

/// Finds every join of the plan's walls. Distances are compared with the tolerance exactly.
/// End clusters (ends within tolerance of each other, but not all of them pairwise) are
/// decided per end: a mitre needs two ends that see only each other, both ways; any chain
/// of three or more unites (see joins.cpp).
/// @param[in] plan  walls with finite coordinates; zero-length walls join nothing.
/// @return the joins; cost O(n log n + k) for n walls and k joined pairs (broad phase on boxes).
[[nodiscard]] Joins find_joins(const Plan& plan);

/// The footprint of a wall after mitring: its corners counter-clockwise, starting at the
/// from-end on the wall's right (the side of -normal, normal = left of from->to), i.e.
/// {from-right, to-right, to-left, from-left}. An unmitred end is square to the wall; a
/// mitred end lies on the mitre line through the crossings of the two walls' side lines
/// (the bisector for equal thicknesses; square when the two walls are collinear, i.e. when
/// the cross product of their directions evaluated in doubles is 0).
/// Corners are the exact points rounded to the nearest double, so a corner shared by the two
/// walls of a mitre comes out bit-identical for both. Cost O(log n); O(1) when the corners
/// are exact in interval arithmetic (axis-aligned walls), else an exact construction
/// (exact::Radical).
/// @pre the wall has positive length and thickness.
[[nodiscard]] std::array<Point2, 4> wall_footprint(const Plan& plan, const Joins& joins,
                                                   std::size_t wall);

}  // namespace roomcad
