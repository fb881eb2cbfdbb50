// SPDX-License-Identifier: GPL-3.0-or-later
// Reading and writing plans as JSON (docs/plan-format.md, versions 1 and 2).
//
// Reading never throws and never crashes: every problem becomes a Diagnostic with the file,
// line, column and JSON pointer (parse_error for malformed JSON and wrong types, invalid_value
// for unknown enums, unsupported format/version/units and numbers that are not finite), and
// unknown fields become `unknown_field` warnings (their values are kept in the plan's `extra`).
// Writing is canonical: fixed key order, every field written, numbers as the shortest decimal
// that reads back to the same double. Saving a canonical file reproduces it byte for byte.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/error.h"
#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad {

/// Most objects of one kind (walls, openings, ...) a plan may hold; more is an invalid_value
/// error on the array. A real building has hundreds; the bound stops one file from asking
/// unbounded memory and time of everything that reads, validates or builds it.
inline constexpr std::size_t kMaxPlanObjects = 1'000'000;

/// Parses a plan from JSON text; `file` names the source in messages.
/// @param[out] report  if given, every problem found is appended to it, errors and warnings
///                     (unknown fields), each with file, line, column and JSON pointer.
/// @return the plan, or its first error (parse_error, invalid_value) when the text holds any.
[[nodiscard]] Result<Plan> read_plan_text(std::string_view text, std::string_view file,
                                          Report* report = nullptr);

/// Reads a plan file as read_plan_text does. An unreadable file, or one larger than
/// kMaxTextFileBytes (io/text_file.h), is an io_error (too_large) naming it, not in `report`.
[[nodiscard]] Result<Plan> read_plan_file(const std::filesystem::path& path,
                                          Report* report = nullptr);

/// @return the canonical JSON text of a plan (ends with a newline).
[[nodiscard]] std::string write_plan_text(const Plan& plan);

/// Writes the canonical text atomically (temporary file in the same folder, then rename):
/// on failure the old file is intact and no temporary file is left.
Status write_plan_file(const Plan& plan, const std::filesystem::path& path);

}  // namespace roomcad
