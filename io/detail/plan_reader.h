// SPDX-License-Identifier: GPL-3.0-or-later
// From the text of a plan file to a Plan, through the field tables (plan/plan_fields.h):
// types, enums, defaults, units, versions and unknown fields.
//
// Why two JSON parsers: simdjson's On-Demand API reads a plan at several hundred MB/s (a
// 100,000-wall plan in a few tens of milliseconds), straight into the Plan with no document
// tree, and tells where each value sits; but it finds malformed JSON late and describes it
// tersely. So a text it refuses is parsed again, on that rare path only, by the positioned
// parser (positioned_json.h), whose messages give the exact line, column and pointer.
#pragma once

#include <cstddef>
#include <string_view>

#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad::io_detail {

/// Reads the plan in `text` (named `file` in messages), appending every problem to `report` in
/// file order: malformed JSON (one parse_error, with line, column and pointer), wrong types and
/// missing required fields (parse_error), unknown enum values, unsupported format, version or
/// units, non-positive cell counts and arrays of more than kMaxPlanObjects objects
/// (invalid_value), and unknown fields (unknown_field warnings, their values kept in `extra`;
/// so are version-2 fields in a version-1 file, which that version does not define). Lengths
/// are converted to metres. Never throws on any text. O(n) in the text's length.
/// @return the plan as read; meaningful only if no error was appended.
[[nodiscard]] Plan read_plan_document(std::string_view text, std::string_view file, Report& report);

}  // namespace roomcad::io_detail
