// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/code.h"

#include <array>
#include <cstddef>
#include <ostream>

namespace roomcad {
namespace {

// In the order of the enum: the table is indexed by the code's value.
constexpr std::array kNames = {
    "parse_error",
    "invalid_value",
    "duplicate_id",
    "unknown_reference",
    "wall_overlap",
    "opening_outside_wall",
    "opening_overlap",
    "opening_blocked",
    "out_of_bounds",
    "slab_overlap",
    "obstruction_overlap",
    "unknown_field",
    "door_above_floor",
    "room_without_door",
    "room_without_window",
    "door_swing_blocked",
    "door_clearance",
    "door_too_narrow",
    "passage_too_narrow",
    "no_turning_circle",
    "room_unreachable",
    "escape_too_far",
    "window_sill_low",
    "window_sill_high",
    "duplicate_object",
    "insolation_short",
    "import_zero_length_wall",
    "import_t_junction",
    "import_split_opening",
    "import_sloped_wall",
    "import_skipped_opening",
    "import_cut_out_shape",
    "import_curved_wall",
    "import_skipped_element",
    "import_approximated",
    "usage_error",
    "io_error",
    "unsupported",
    "too_large",
    "precondition",
    "not_buildable",
    "edit_refused",
    "lock_timeout",
    "check_failed",
    "internal",
};
static_assert(kNames.size() == std::size_t(Code::internal) + 1, "one name per code");

}  // namespace

std::string_view to_string(Code code) { return kNames[static_cast<std::size_t>(code)]; }

std::ostream& operator<<(std::ostream& out, Code code) { return out << to_string(code); }

std::optional<Code> parse_code(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<Code>(i);
  return std::nullopt;
}

bool is_finding(Code code) { return code < Code::usage_error; }

ExitStatus exit_status_of(Code code) {
  switch (code) {
    case Code::usage_error:
    case Code::io_error:
    case Code::unsupported:
    case Code::too_large:
    case Code::precondition:
    case Code::lock_timeout:
    case Code::internal: return kExitCannotRun;
    default: return kExitPlanErrors;
  }
}

}  // namespace roomcad
