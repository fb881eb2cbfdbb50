// SPDX-License-Identifier: GPL-3.0-or-later
// Levels (plan format version 2) resolved to absolute heights: where a wall's base and a slab's
// top are, and the part of a plan on one level. What every module that places objects in z
// (the build, validation, drawings per level) reads, so that they agree to the bit.
#pragma once

#include <string_view>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad {

/// @return the level named `id`, or nullptr when `id` is empty or names no level. O(levels).
[[nodiscard]] const Level* find_level(const Plan& plan, std::string_view id);

/// @return the elevation (m) of the level named `id`; 0 when `id` is empty or names no level
///         (an unknown_reference that validation reports). O(levels).
[[nodiscard]] double level_elevation(const Plan& plan, std::string_view id);

/// @return the z (m) of the wall's base: its level's elevation plus its `base`, rounded once to
///         the nearest double (docs/plan-format.md, "Levels"). O(levels).
[[nodiscard]] double base_z(const Plan& plan, const Wall& wall);

/// @return the z (m) of the slab's top: its level's elevation plus its `top`, rounded once.
[[nodiscard]] double top_z(const Plan& plan, const Slab& slab);

/// The plan with every wall's `base` and every slab's `top` made absolute (base_z, top_z) and
/// their `level` cleared, levels kept: what code written for version 1's single storey reads.
/// O(levels * (walls + slabs)).
[[nodiscard]] Plan with_absolute_heights(Plan plan);

/// The objects of one level: its walls and slabs, the openings of those walls, every light and
/// camera, the site and the levels. For drawings and exports of one storey (`--level ID`).
/// @pre find_level(plan, level) != nullptr (else PreconditionError). O(walls + openings + slabs).
[[nodiscard]] Plan plan_of_level(const Plan& plan, std::string_view level);

/// What a command shows for `--level ID`: plan_of_level, or the whole plan for an empty
/// `level`. @return a usage_error naming the level and the plan's levels when it names none.
/// O(walls + openings + slabs).
[[nodiscard]] Result<Plan> select_level(const Plan& plan, std::string_view level);

}  // namespace roomcad
