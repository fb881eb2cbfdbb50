// SPDX-License-Identifier: GPL-3.0-or-later
// A proposed repair of one finding: the edits that clear it, or why there are none. What the
// proposers (parallel_walls.h, wall_ends.h, openings.h, slabs.h) return and repair_plan
// applies, checks and keeps or drops.
#pragma once

#include <string>
#include <vector>

#include "plan/plan.h"
#include "repair/repair.h"
#include "validation/report.h"

namespace roomcad::detail {

struct Proposal {
  FindingKey finding;
  std::vector<RepairEdit> edits;  ///< in the order they apply
};

/// @return how much the volume may change when `p`'s objects move by its largest `moves`: that
///         move times a bound on their surface (each object's box before the edit). 0 for a
///         proposal that keeps the union. O(objects of the plan).
[[nodiscard]] double volume_slack(const Plan& plan, const Proposal& p);

/// A proposal, or the reason none clears the finding.
struct Attempt {
  std::vector<Proposal> proposals;  ///< empty: none, see reason
  std::string reason;
};

[[nodiscard]] inline Attempt refused(std::string reason) { return {{}, std::move(reason)}; }

/// @return the finding's key (its code and objects).
[[nodiscard]] FindingKey key_of(const Diagnostic& finding);

/// Applies one edit: its new values set on its object, or the object removed.
/// @pre the object exists and each key is one the repairs write (repair/detail/proposal.cpp).
void apply_edit(Plan& plan, const RepairEdit& edit);

/// Adds `key`'s old and new values to the edit, when they differ.
template <class T>
void record_field(RepairEdit& edit, const char* key, const T& old_value, const T& new_value) {
  if (old_value == new_value) return;
  edit.old_values.emplace_back(key, old_value);
  edit.new_values.emplace_back(key, new_value);
}

/// @return "needs a move of 0.04 m, more than the tolerance 0.01 m".
[[nodiscard]] std::string too_far(double move, double tolerance);

}  // namespace roomcad::detail
