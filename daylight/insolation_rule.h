// SPDX-License-Identifier: GPL-3.0-or-later
// The insolation rule (insolation_short, validation/rule_set.h's InsolationRule): each room it
// applies to must get its hours of direct sun on the rule's days. A finding names the room and
// its best window, the hours it gets and needs, and a fix checked by recomputing the sun of the
// plan as the fix would leave it.
#pragma once

#include "mesh/solid_mesh.h"
#include "plan/plan.h"
#include "validation/report.h"
#include "validation/rule_set.h"

namespace roomcad {

/// @return the insolation_short findings of `plan` under `rules` (none unless the rule is
///         enabled and the site has a location), at the rule's severity.
/// @param[in] solid  build_model(plan).walls
/// Cost: one insolation() per day of the rule, plus for each of the first few rooms that fall
/// short up to ten candidate fixes, each a validation, a build and one window's sun.
[[nodiscard]] Report check_insolation(const Plan& plan, const SolidMesh& solid,
                                      const RuleSet& rules);

/// Appends check_insolation's findings to `report`, building the plan's solid for them (what
/// `roomcad validate`, `report` and the Python module's validate do). A plan whose solid
/// cannot be built gets one insolation_short finding saying so. Nothing when the rule is off
/// or the site has no location.
void add_insolation_findings(const Plan& plan, const RuleSet& rules, Report& report);

}  // namespace roomcad
