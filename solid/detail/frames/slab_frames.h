// SPDX-License-Identifier: GPL-3.0-or-later
// A slab as the builders take it: its area (outline minus holes) cut into convex pieces whose
// corners are the slab's own points, or rectangles between its corners' coordinates where every
// edge runs along x or y (no new numbers, so every piece is exact in the plan's doubles),
// between its bottom and its top (absolute: levels resolved).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

struct SlabFrame {
  std::size_t slab = 0;            ///< index into Plan::slabs
  std::string id;                  ///< the slab's id, for messages
  Polygon outline;                 ///< laid into the walls along it (slab_edges.h)
  std::vector<Polygon> holes;      ///< likewise
  std::vector<Polygon> pieces;     ///< convex, counter-clockwise, together the slab's area
  double bottom = 0.0, top = 0.0;  ///< top - thickness, top
  double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;  ///< the outline's box
  Color color;
};

/// The slabs of a plan with absolute heights (with_absolute_heights), in plan order, their
/// edges along walls laid into the walls (slab_edges.h); a slab with no volume in doubles
/// (thickness <= 0, or an outline of no area) has none and is left out.
/// @param[in] walls  the plan's wall frames (make_wall_frames)
/// @throws PreconditionError (not_buildable) naming the slab whose outline or holes cross
///         themselves or each other (validation's invalid_value says the same). O(n log n)
///         for n corners (a constrained Delaunay triangulation, then triangles merged while
///         the union stays convex), or O(r n) for the rectangles of r rows.
[[nodiscard]] std::vector<SlabFrame> make_slab_frames(const Plan& plan,
                                                      const std::vector<WallFrame>& walls);

}  // namespace roomcad::detail
