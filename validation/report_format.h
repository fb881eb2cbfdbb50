// SPDX-License-Identifier: GPL-3.0-or-later
// Printing a Report: the JSON object of docs/plan-format.md ("Validation codes") for
// tools, and plain text for people.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "validation/report.h"
#include "validation/report_diff.h"

namespace roomcad {

/// What the printed report adds to the spec's fields; the defaults print exactly those.
struct ReportFormatOptions {
  bool ids = false;                              ///< each item's "id" (item_ids)
  const ReportComparison* comparison = nullptr;  ///< each item's status, and the fixed items
  std::string baseline_file;                     ///< the baseline named in the output
  std::string plan_file = "PLAN";                ///< the plan named in fixes' edit commands
  /// Text: the items printed in full; the rest are counted (`--max-findings`).
  std::size_t max_items = std::numeric_limits<std::size_t>::max();
  /// Text: each item's level (item_levels), for the summary by level; null for none.
  const std::vector<std::string>* item_levels = nullptr;
};

/// Text reports of at least this many items end with a summary by code and level.
inline constexpr std::size_t kTallyFrom = 10;

/// @return `{"ok": bool, "errors": [...], "warnings": [...]}`, one item per line, each with
/// `code`, `objects`, `message`, then `where` (a point `[x, y]` or a box `[[xmin, ymin],
/// [xmax, ymax]]`) when set, `fix` when not empty, `edits` (the fix as edits, each with
/// `op` set|add|rm, `id`, `fields`, `cascade` for rm, and its `command`) when it has them,
/// and `file`, `line`, `column`, `pointer` when the item has a source location. With
/// `options.ids` each item also has `id`; with a comparison, `status` ("new" or
/// "unchanged"), and the object ends with `"baseline": {"file", "new", "unchanged",
/// "fixed": [items]}`. Ends with a newline.
[[nodiscard]] std::string format_report_json(const Report& report,
                                             const ReportFormatOptions& options = {});

/// @return one item as format_report_json writes it (no id or status), on one line.
[[nodiscard]] std::string format_item_json(const Diagnostic& item,
                                           const std::string& plan_file = "PLAN");

/// @return one block per item, errors and warnings in report order:
/// `error[code] a, b: message`, then indented `at: ...` (where), `fix: ...` and `edit: roomcad
/// ...` lines; with a comparison each block starts with `new` or `unchanged`, and the fixed
/// items follow under `fixed since FILE:`. Only the first `options.max_items` items are
/// printed in full, then a line counting the rest; a report of kTallyFrom items or more, or
/// one cut short, ends with format_report_tally's summary.
/// @param[in] colour  add ANSI colours (for a terminal)
[[nodiscard]] std::string format_report_text(const Report& report, bool colour,
                                             const ReportFormatOptions& options = {});

/// @return "2 errors, 1 warning", or "no problems"; with a comparison, then "; against
/// FILE: 1 new, 2 unchanged, 3 fixed".
[[nodiscard]] std::string format_report_summary(const Report& report,
                                                const ReportFormatOptions& options = {});

}  // namespace roomcad
