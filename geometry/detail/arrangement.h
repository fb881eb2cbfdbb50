// SPDX-License-Identifier: GPL-3.0-or-later
// The faces of the walls' centre-line arrangement, behind a plain header (CGAL inside).
#pragma once

#include <cstddef>
#include <vector>

#include "plan/plan.h"

namespace roomcad::detail {

/// One side of a bounded face: a piece of wall `wall`'s centre line, the face on its left.
struct FaceEdge {
  Point2 source;
  Point2 target;
  std::size_t wall = 0;
};

/// A bounded face: its outer boundary counter-clockwise, and the area of its holes.
struct Face {
  std::vector<FaceEdge> boundary;
  double hole_area = 0.0;  ///< centre-line area of the regions nested inside (square metres)
};

/// @param segments  centre-line pieces (from, to); none of zero length. FaceEdge::wall is an
///                  index into this list.
///                  Crossings and overlaps are constructed exactly (Epeck).
/// @return the bounded faces of their arrangement. O((n + k) log n) for n pieces and k
///         crossings.
[[nodiscard]] std::vector<Face> find_bounded_faces(
    const std::vector<std::pair<Point2, Point2>>& segments);

}  // namespace roomcad::detail
