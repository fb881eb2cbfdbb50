// SPDX-License-Identifier: GPL-3.0-or-later
// Groups of walls that the build makes apart: the window rebuilds only the groups an edit
// touched (view/model_cache.h).
//
// Two walls are in one group when they are joined (geometry/joins.h) or their footprints come
// within kGroupMargin of each other, and groups are closed under that (connected components).
// Walls of different groups are then neither joined nor touching, so the wall solid of the plan
// is the disjoint union of the groups' solids, each built from its walls and their openings
// alone, as build_model builds any walls that meet nothing else (solid/build_model.h).
// Where that cannot be told from the plan (slabs, arc walls, a wall without positive finite
// length and thickness, repeated wall ids, an opening in no wall), every wall is one group.
#pragma once

#include <cstddef>
#include <vector>

#include "plan/plan.h"

namespace roomcad {

/// Footprints closer than this (metres) put their walls in one group: far above the few ulps
/// within which a build snaps corners together, far below anything drawn apart on purpose.
inline constexpr double kGroupMargin = 1e-3;

/// Splits the plan's walls into groups the build makes apart (see above).
/// @param[in] plan  any plan, with errors or without
/// @return groups of wall indices (into plan.walls), each ascending, ordered by first wall;
///         every wall in exactly one group (none for a plan without walls).
///         O(n log^2 n + k) for n walls and k meeting pairs.
[[nodiscard]] std::vector<std::vector<std::size_t>> find_wall_groups(const Plan& plan);

}  // namespace roomcad
