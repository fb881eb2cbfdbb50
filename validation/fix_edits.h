// SPDX-License-Identifier: GPL-3.0-or-later
// A finding's fix as edits (Diagnostic::edits): applying them to a plan, and writing them as
// the roomcad commands that make them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad {

/// Applies the edits in order with modeling's edit functions (set_field, add_opening,
/// remove_object). Applying a rule finding's edits removes that finding (each rule's tests
/// check it).
/// @throws PreconditionError (from plan/plan_edit.h) if an edit does not apply, e.g. to a
///         plan that changed since the finding; the plan may then hold the earlier edits.
void apply_fix_edits(Plan& plan, const std::vector<FixEdit>& edits);

/// @return the command line that makes the edit on `plan_file`:
///         `roomcad set plan.json d1 hinge=right`, `roomcad add plan.json door --id door-1
///         --wall w3 --offset 1.2 --width 0.9`, `roomcad rm plan.json w9 --cascade`.
[[nodiscard]] std::string edit_command(const FixEdit& edit, std::string_view plan_file);

}  // namespace roomcad
