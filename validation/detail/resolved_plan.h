// SPDX-License-Identifier: GPL-3.0-or-later
// The plan as the geometry checks see it (plan format version 2): levels resolved to absolute
// heights (plan_levels.h), and each arc wall replaced by the chords it is built as
// (arc_chords.h), which keep its id, so that every verdict about walls is the version-1
// verdict about straight walls, exact for the polyline that the wall is.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "plan/plan.h"
#include "validation/detail/checks.h"

namespace roomcad::detail {

struct ResolvedPlan {
  /// Levels resolved; walls: one per straight wall, one per chord of an arc (same id, the
  /// chord's share of a sloped top); openings: those of straight walls as they are, those of
  /// an arc wall cut into one piece per chord they cross (same id); slabs resolved.
  Plan plan;
  Usable usable;                         ///< by index of `plan`'s walls and openings
  std::vector<std::size_t> source_wall;  ///< by wall of `plan`: its wall in the input
};

/// Resolves `plan` (whose usable walls and hosts are `usable`, from check_values/check_ids)
/// for the geometry checks (with_absolute_heights, then with_arcs_as_chords).
/// O(walls + chords + openings x chords of their wall).
[[nodiscard]] ResolvedPlan resolve_plan(const Plan& plan, const Usable& usable);

}  // namespace roomcad::detail
