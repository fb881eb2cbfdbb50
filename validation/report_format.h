// Printing a Report: the JSON object of docs/plan-format.md ("Validation codes") for
// tools, and plain text for people.
#pragma once

#include <string>

#include "validation/report.h"

namespace roomcad {

/// @return `{"ok": bool, "errors": [...], "warnings": [...]}`, one item per line, each with
/// `code`, `objects`, `message`, then `where` (a point `[x, y]` or a box `[[xmin, ymin],
/// [xmax, ymax]]`) when set, `fix` when not empty, and `file`, `line`, `column`, `pointer`
/// when the item has a source location. Ends with a newline.
[[nodiscard]] std::string format_report_json(const Report& report);

/// @return one block per item, errors and warnings in report order:
/// `error[code] a, b: message`, then indented `at: ...` (where) and `fix: ...` lines.
/// @param[in] colour  add ANSI colours (for a terminal)
[[nodiscard]] std::string format_report_text(const Report& report, bool colour);

/// @return "2 errors, 1 warning", or "no problems".
[[nodiscard]] std::string format_report_summary(const Report& report);

}  // namespace roomcad
