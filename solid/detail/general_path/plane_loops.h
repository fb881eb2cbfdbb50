// SPDX-License-Identifier: GPL-3.0-or-later
// Linking the boundary pieces of one plane's faces into loops (plane_faces.h): each piece
// runs between two vertex ids with its face on its left; where a vertex starts more than one
// piece of a face (two parts of it touch there), the piece that turns most sharply is taken,
// so that touching parts become separate loops and no loop crosses itself.
#pragma once

#include <cstddef>
#include <vector>

#include "solid/detail/general_path/exact_planes.h"

namespace roomcad::detail {

/// A directed boundary piece of a face: from vertex `from` to vertex `to` (ids into a point
/// table), along `line`, in direction dir * (n x n_line) for the plane's normal n.
struct DirectedPiece {
  std::size_t from = 0, to = 0;
  PlaneRef line;
  int dir = 1;
};

/// A closed loop: pieces in order, each ending where the next starts.
struct PieceLoop {
  std::vector<DirectedPiece> pieces;
  bool is_hole = false;  ///< clockwise seen from the face's outside
};

/// Links the pieces of one face (all with the face on their left seen from `view` times the
/// plane's normal) into loops.
/// @param[in]     view    +1: the face is seen from the plane's positive side, -1: negative
/// @param[in,out] points  the points, by vertex id (a cache of their exact coordinates)
/// @return the loops. O(n log n) for n pieces, plus angular sorts at shared vertices.
/// @throws PreconditionError (internal) if a loop does not close.
[[nodiscard]] std::vector<PieceLoop> link_loops(PlaneRef plane, int view,
                                                std::vector<DirectedPiece> pieces,
                                                PointCache& points);

}  // namespace roomcad::detail
