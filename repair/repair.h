// SPDX-License-Identifier: GPL-3.0-or-later
// Repairing a plan: the drafting noise of real plans (walls drawn twice or into their
// neighbours, slabs drawn over one another, openings a hair past their wall) cleared by edits
// that move the built solid by at most a stated tolerance, and by nothing where the union of
// the solids allows. docs/plan-format.md ("Repair") gives the report's JSON.
//
// Guarantees (tests/repair/): the solid built from the repaired plan lies within Hausdorff
// distance `tolerance` of the one built from the original with --force; edits that keep the
// union leave the analytic volume unchanged; repairing a repaired plan changes nothing; a
// plan with nothing to repair comes back equal; the result does not depend on threads.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/code.h"
#include "core/error.h"
#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad {

struct RepairOptions {
  double tolerance = 0.01;   ///< metres the built solid may move, >= 0
  std::vector<Code> only{};  ///< the error codes to repair; empty: every code repair knows
};

/// What an edit did to its object (the JSON's `change`).
enum class RepairChange { merge, trim, extend, snap, cut, move, shorten, remove };
/// @return the JSON spelling: "merge", ..., "delete" for remove.
[[nodiscard]] std::string_view to_string(RepairChange change);

/// A field's value before or after an edit: a number, a point, an id or a polygon.
using RepairValue = std::variant<double, Point2, std::string, Polygon>;
using RepairFields = std::vector<std::pair<std::string, RepairValue>>;

/// A finding by its code and objects, as validation reports it.
struct FindingKey {
  Code code = Code::wall_overlap;
  std::vector<std::string> objects;
  friend auto operator<=>(const FindingKey&, const FindingKey&) = default;
};

/// One edit of one object.
struct RepairEdit {
  std::string object;
  RepairChange change = RepairChange::trim;
  RepairFields old_values;  ///< the fields it changed, as they were (delete: the object's place)
  RepairFields new_values;  ///< as they are now (empty for delete)
  std::vector<FindingKey> clears;  ///< the findings it was made for and that are gone
  double moves = 0.0;              ///< the most the built solid can move because of it, metres
};

/// An error left, with why.
struct RemainingFinding {
  Diagnostic finding;
  std::string reason;
};

struct RepairResult {
  Plan plan;  ///< the repaired plan (equal to the input when no edit was made)
  double tolerance = 0.0;
  std::map<Code, std::size_t> before;  ///< error counts per code before
  std::map<Code, std::size_t> after;   ///< and after
  std::vector<RepairEdit> edits;       ///< in the order made
  std::vector<RemainingFinding> remaining;
};

/// Repairs what it can of the plan's errors (see the file comment for what and how).
/// Deterministic: single-threaded rounds of validate, propose, apply and check.
/// @return the result, or invalid_value for a tolerance that is negative or not finite.
/// Cost: a few rounds of validation, O(n log n) each, plus one analytic volume per round that
/// claims to keep the union (more when a claim fails and the round is split to find it).
[[nodiscard]] Result<RepairResult> repair_plan(const Plan& plan, const RepairOptions& options = {});

}  // namespace roomcad
