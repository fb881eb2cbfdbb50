// SPDX-License-Identifier: GPL-3.0-or-later
// Comparing two reports of the same plan before and after an edit: which errors are new.
// Shared by the edit commands (cli/edit_session) and the window (view/), which both judge an
// edit by the errors it introduces rather than by the errors the plan already had.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "validation/report.h"

namespace roomcad {

/// The errors of `after` beyond those of `before`, counted per identity: an error's code and
/// the sorted ids it involves (messages and places change when objects move, the problem
/// does not). Two overlaps of the same walls before and one after introduce nothing; warnings
/// are ignored.
/// @return the new errors, in `after`'s order. O(n log n) in items.
[[nodiscard]] Report introduced_errors(const Report& before, const Report& after);

/// @return each item's identity across revisions of a plan, by the same rule: its code and
///         its sorted object ids ("door_clearance:d1+w3"); an item with no objects is named by
///         its JSON pointer or, failing that, its message. The k-th repeat of an identity in
///         the report gets "#k" (k >= 2). Stable while the objects keep their ids. O(n log n).
[[nodiscard]] std::vector<std::string> item_ids(const Report& report);

/// How an item of a report compares with a baseline report (an earlier revision).
enum class ItemStatus : std::uint8_t { added, unchanged };

/// @return "new" or "unchanged".
[[nodiscard]] std::string_view to_string(ItemStatus status);

struct ReportComparison {
  std::vector<std::string> ids;    ///< item_ids of the current report
  std::vector<ItemStatus> status;  ///< by item of the current report
  Report fixed;                    ///< items of the baseline that are gone
  std::vector<std::string> fixed_ids;
};

/// Compares a report with the report of an earlier revision by item_ids: errors, warnings
/// and rule findings alike. O(n log n).
[[nodiscard]] ReportComparison compare_reports(const Report& baseline, const Report& current);

}  // namespace roomcad
