// From a parsed JSON document to a Plan: types, enums, defaults, units and unknown fields.
#pragma once

#include <string_view>

#include "io/detail/positioned_json.h"
#include "modeling/plan.h"
#include "validation/report.h"

namespace roomcad::io_detail {

/// Reads the plan held by `doc` (parsed from `text`, named `file` in messages), appending every
/// problem to `report`: wrong types and missing required fields (parse_error), unknown enum
/// values, unsupported format/version/units and non-positive cell counts (invalid_value), and
/// unknown fields (unknown_field warnings, their values kept in `extra`). Lengths are converted
/// to metres. Never throws on any document. O(n) in the document size.
/// @return the plan as read; meaningful only if no error was appended.
[[nodiscard]] Plan read_plan_document(const PositionedJson& doc, std::string_view text,
                                      std::string_view file, Report& report);

}  // namespace roomcad::io_detail
