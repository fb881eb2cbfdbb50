// SPDX-License-Identifier: GPL-3.0-or-later
// The one vocabulary of codes roomcad speaks: every finding of validation (the codes of the plan
// format, docs/plan-format.md), every warning, and every reason a command or a library call
// fails. A code is stable: it is printed, written in JSON, raised to Python and read by
// outside tests, so names are never changed, only added.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string_view>

namespace roomcad {

/// Why something is wrong. Codes up to `out_of_bounds`, `slab_overlap` and the rule codes are
/// the plan format's; the import and failure codes are roomcad's own.
enum class Code : std::uint8_t {
  // Errors of a plan (the plan format's "Validation codes").
  parse_error,           ///< not JSON, a field of the wrong type, a required field missing
  invalid_value,         ///< not finite, not positive, unknown enum, unsupported format
  duplicate_id,          ///< two objects share an id
  unknown_reference,     ///< an opening names no wall, an object names no level
  wall_overlap,          ///< two walls that are not joined share interior volume
  opening_outside_wall,  ///< an opening's outline is not inside its wall
  opening_overlap,       ///< two openings of one wall share interior area
  opening_blocked,       ///< an opening's hole shares interior volume with a wall or slab
  out_of_bounds,         ///< outside the site or above max_height
  slab_overlap,          ///< two slabs share interior volume (version 2)
  obstruction_overlap,   ///< an obstruction shares interior volume with a wall or slab
  // Warnings of a plan.
  unknown_field,        ///< a field the format does not define (kept as is)
  door_above_floor,     ///< a door whose sill is above its wall's base
  room_without_door,    ///< a closed room no door leads into
  room_without_window,  ///< a closed room with no window
  // Rule sets (`validate --rules`).
  door_swing_blocked,
  door_clearance,
  door_too_narrow,
  passage_too_narrow,
  no_turning_circle,
  room_unreachable,
  escape_too_far,
  window_sill_low,
  window_sill_high,
  duplicate_object,
  insolation_short,  ///< a room gets less direct sun than its rule set asks (rule `insolation`)
  // What importing a home had to approximate or leave out (warnings).
  import_zero_length_wall,
  import_t_junction,
  import_split_opening,
  import_sloped_wall,
  import_skipped_opening,
  import_cut_out_shape,
  import_curved_wall,
  import_skipped_element,
  import_approximated,  ///< an element read with a simpler shape than it has (IFC import)
  // Why a command or a call could not do its work.
  usage_error,    ///< a bad argument or option (exit 2)
  io_error,       ///< a file could not be read or written (exit 2)
  unsupported,    ///< a file format or extension roomcad does not read or write
  too_large,      ///< past one of the documented limits (file size, pixels, objects)
  precondition,   ///< a documented precondition of a function does not hold
  not_buildable,  ///< the plan's solid cannot be built as asked (names the objects)
  edit_refused,   ///< an edit would introduce errors, or is not allowed on this plan
  lock_timeout,   ///< another editor held the plan's lock for longer than --wait
  check_failed,   ///< a result's own check failed (build --check)
  internal,       ///< a bug: an internal invariant did not hold
};

/// @return the code's name as the format and the JSON write it ("wall_overlap").
[[nodiscard]] std::string_view to_string(Code code);

/// Writes to_string(code): codes print by name in logs and test failures.
std::ostream& operator<<(std::ostream& out, Code code);

/// @return the code named `name`, or nullopt. O(number of codes).
[[nodiscard]] std::optional<Code> parse_code(std::string_view name);

/// @return true for the codes that are findings about a plan (validation, rules, import),
///         false for the codes of a failure to run (usage_error ... internal).
[[nodiscard]] bool is_finding(Code code);

/// The exit status of every command (docs/plan-format.md): 0 success, 1 the plan has errors or
/// the command's own check failed, 2 the command could not run.
enum ExitStatus : int { kExitOk = 0, kExitPlanErrors = 1, kExitCannotRun = 2 };

/// @return the exit status a command ends with when it fails with `code`: kExitCannotRun for
///         usage, I/O, unsupported, too large, precondition (a caller's bad argument), lock and
///         internal failures; kExitPlanErrors for findings about the plan, a solid that cannot be
///         built, refused edits and failed checks.
[[nodiscard]] ExitStatus exit_status_of(Code code);

}  // namespace roomcad
