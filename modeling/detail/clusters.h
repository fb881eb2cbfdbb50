// Which walls take the fast path and which go to CGAL together (clusters).
//
// A wall needs the general path if it takes part in a unite join (T, X, three or more walls),
// is mitred to a wall of another base or height, has a hole not clear of a mitred end, or
// meets a wall it is not joined to (their boxes touch). A cluster is a connected group of
// walls (joined or touching) holding such a wall; every other wall is built alone on the fast
// path. So fast walls and clusters never touch, and the wall solid is their disjoint union
// (a fast wall's mitre partner is always a fast wall: mitred walls are joined).
#pragma once

#include <cstddef>
#include <vector>

#include "modeling/build_model.h"
#include "modeling/detail/wall_frame.h"

namespace roomcad::detail {

/// A unit of work: one fast wall, or one CGAL cluster, as indices into the frames.
struct WorkItem {
  bool general = false;
  std::vector<std::size_t> walls;  ///< ascending
};

/// Splits the walls into work items, ordered by their first wall.
/// @param[in] path  BooleanPath::cgal puts every wall in a cluster.
/// @return the items; every wall is in exactly one. O(n log^2 n + k) for k touching pairs.
[[nodiscard]] std::vector<WorkItem> plan_work(const std::vector<WallFrame>& frames,
                                              const Joins& joins, BooleanPath path);

}  // namespace roomcad::detail
