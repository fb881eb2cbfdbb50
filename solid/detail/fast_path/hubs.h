// SPDX-License-Identifier: GPL-3.0-or-later
// The fast path at nodes where three or four walls end (the grid case): the union of their
// boxes near the node is a convex "hub" polygon whose corners are the crossings of adjacent
// walls' facing side lines (for two collinear walls, their shared side line at the node).
// Each wall (arm) ends without a cap on the hub's corners, like a mitre, and the hub adds
// only its top and bottom faces. Valid when all walls at the node end there (identical end
// points), have equal base and height, adjacent walls are 90 to 180 degrees apart (collinear
// ones of equal thickness), and each corner lies on both its arms' side lines ahead of the
// node: then arms and hub tile the union exactly. (An arm shorter than the corner reaches is
// a bow-tie, which sends the arm's walls to the general path: has_crossed_footprint.)
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

struct Hub {
  std::vector<std::pair<std::size_t, WallEnd>> arms;  ///< counter-clockwise around the node
  std::vector<Point2> corners;  ///< corners[k]: between arm k and arm k + 1, counter-clockwise
};

/// Finds the nodes that qualify as hubs (see above).
/// @return hubs ordered by their first arm's wall; every unite join between two arms of a
///         hub is explained by it. O(n log n) for n walls.
[[nodiscard]] std::vector<Hub> find_hubs(const std::vector<WallFrame>& frames, const Joins& joins);

/// Ends each arm of the hub on the hub's corners, without a cap.
void attach_hub(const Hub& hub, std::vector<WallFrame>& frames);

/// @return the hub's top and bottom faces, owned by its first arm's wall. O(corners).
[[nodiscard]] FaceSoup build_hub(const Hub& hub, const std::vector<WallFrame>& frames);

}  // namespace roomcad::detail
