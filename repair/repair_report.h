// SPDX-License-Identifier: GPL-3.0-or-later
// Printing a repair (repair.h): the JSON object of docs/plan-format.md ("Repair") for tools,
// and plain text for people.
#pragma once

#include <string>

#include "repair/repair.h"

namespace roomcad {

/// @return `{"tolerance", "before", "after", "edits": [...], "remaining": [...]}`, one edit
/// and one remaining finding per line; numbers as the shortest text that reads back the same.
/// Ends with a newline.
[[nodiscard]] std::string format_repair_json(const RepairResult& repair);

/// @return one line per edit (`trim wall 'w2': to (3, 4.1) -> (3, 4); clears wall_overlap
/// w1, w2; moves 0 m`), the error counts before and after per code, and each remaining
/// error with why it was left. Lengths in millimetres. `verbose`: every edit, else the first
/// 20 and a count of the rest.
[[nodiscard]] std::string format_repair_text(const RepairResult& repair, bool verbose);

/// @return "12 edits clear 15 of 17 errors, 2 remain; the solid moves at most 4 mm".
[[nodiscard]] std::string format_repair_summary(const RepairResult& repair);

}  // namespace roomcad
