// From a parsed JSON document to a Plan: types, enums, defaults, units and unknown fields.
#pragma once

#include <cstddef>
#include <string_view>

#include "io/detail/positioned_json.h"
#include "modeling/plan.h"
#include "validation/report.h"

namespace roomcad::io_detail {

/// Most objects of one kind (walls, openings, lights or cameras) a plan may hold; more is an
/// invalid_value error on the array. A real building has hundreds; the bound stops one file
/// from asking unbounded memory and time of everything that reads, validates or builds it.
inline constexpr std::size_t kMaxPlanObjects = 1'000'000;

/// Reads the plan held by `doc` (parsed from `text`, named `file` in messages), appending every
/// problem to `report`: wrong types and missing required fields (parse_error), unknown enum
/// values, unsupported format/version/units, non-positive cell counts and arrays of more than
/// kMaxPlanObjects objects (invalid_value), and unknown fields (unknown_field warnings, their
/// values kept in `extra`). Lengths are converted to metres. Never throws on any document. O(n) in the document size.
/// @return the plan as read; meaningful only if no error was appended.
[[nodiscard]] Plan read_plan_document(const PositionedJson& doc, std::string_view text,
                                      std::string_view file, Report& report);

}  // namespace roomcad::io_detail
