// SPDX-License-Identifier: GPL-3.0-or-later
// Which walls take the fast path and which go to a boolean path together (clusters).
//
// A wall needs the general path if it takes part in a unite join that no hub or tee builds
// (solid/detail/fast_path/hubs.h, solid/detail/fast_path/tees.h), is mitred to a wall of another
// base or height or whose mitred end face is not its own (a straight run from one thickness to
// another), has a hole not clear of a capless end, or meets a wall it is not joined to (their boxes
// touch). A cluster is a connected group of walls (joined or touching) holding such a wall; every
// other wall is built alone on the fast path, and every hub among fast walls adds its top and
// bottom. So fast pieces and clusters never touch, and the wall solid is their disjoint union. A
// slab joins the cluster of every wall and slab its box meets (it needs the general path).
#pragma once

#include <cstddef>
#include <vector>

#include "solid/build_model.h"
#include "solid/detail/fast_path/hubs.h"
#include "solid/detail/fast_path/tees.h"
#include "solid/detail/frames/slab_frames.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

/// A unit of work: one fast wall, one cluster (general or Nef path), or one hub.
struct WorkItem {
  enum class Kind { fast_wall, cluster, hub } kind = Kind::fast_wall;
  std::vector<std::size_t> walls;  ///< ascending indices into the frames (one for a fast wall)
  std::size_t hub = 0;             ///< index into Work::hubs, for a hub
  std::vector<std::size_t> slabs;  ///< ascending indices into the slab frames, for a cluster
};

struct Work {
  std::vector<WorkItem> items;         ///< ordered by first wall; hubs after the walls
  std::vector<WallFrame> fast_frames;  ///< the frames with every used hub attached
  std::vector<Hub> hubs;
  std::vector<Tee> tees;
};

/// Splits the walls into work items.
/// @param[in] path  BooleanPath::general and ::nef put every wall in a cluster.
/// @param[in] slabs  make_slab_frames' (empty: no slabs)
/// @return the work; every wall and slab is in exactly one item. O(n log^2 n + k) for n walls
///         and slabs and k touching pairs.
[[nodiscard]] Work plan_work(const std::vector<WallFrame>& frames, const Joins& joins,
                             BooleanPath path, const std::vector<SlabFrame>& slabs = {});

}  // namespace roomcad::detail
