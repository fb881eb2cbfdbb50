// SPDX-License-Identifier: GPL-3.0-or-later
// Levels (plan format version 2, docs/plan-format.md "Version 2"): where a wall or slab stands
// in absolute z, and the part of a plan that belongs to one level. One place for the rule
// "a wall's `base` (a slab's `top`) is measured from its level's elevation; without a level,
// or naming a level the plan does not have, from z = 0", so that the build, validation and
// render agree on it. An unknown level is validation's `unknown_reference`; here it places
// the object as version 1 does, so that `--force` builds what it can.
#pragma once

#include <string_view>

#include "modeling/plan.h"

namespace roomcad {

/// @return the level with this id, or nullptr (also for an empty id). O(levels).
[[nodiscard]] const Level* find_level(const Plan& plan, std::string_view id);

/// @return the elevation of the level named `id` in metres; 0 for no level or an unknown one.
///         O(levels).
[[nodiscard]] double level_elevation(const Plan& plan, std::string_view id);

/// @return the absolute z of the wall's base, metres (its level's elevation + base). O(levels).
[[nodiscard]] double wall_base_z(const Plan& plan, const Wall& wall);

/// @return the absolute z of the slab's top face, metres (its level's elevation + top).
///         O(levels).
[[nodiscard]] double slab_top_z(const Plan& plan, const Slab& slab);

/// The plan with every wall's `base` and slab's `top` made absolute and their `level`
/// cleared: what the build works on. Levels themselves are kept (for names). O(n + levels).
[[nodiscard]] Plan with_levels_resolved(const Plan& plan);

/// The plan with only the walls and slabs of level `id` and the openings in those walls
/// (positions unchanged: the level keeps its elevation). For `build --level`.
/// @pre find_level(plan, id) != nullptr. O(n log n).
[[nodiscard]] Plan plan_of_level(const Plan& plan, std::string_view id);

}  // namespace roomcad
