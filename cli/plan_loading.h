// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the plan a command works on, with its problems printed the same way by every command.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "io/plan_lock.h"
#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad::cli {

/// A plan read for a command, or why there is none.
struct LoadedPlan {
  std::optional<Plan> plan;  ///< set when the file was read and has no errors
  std::string text;          ///< the file's bytes, when it could be read
  Report report;             ///< what reading found (errors and warnings)
  int exit_status = 0;       ///< when `plan` is empty: kExitCannotRun (unreadable) or kExitPlanErrors
};

/// Reads the plan file `path` for subcommand `command`. Prints every problem, warnings too, to
/// stderr as text (coloured when stderr is a terminal), then one summary line if there were
/// errors. A file that cannot be read (missing, a directory, no permission) gives kExitCannotRun;
/// a file that is read but is not a valid plan gives kExitPlanErrors.
[[nodiscard]] LoadedPlan load_plan(std::string_view command, const std::filesystem::path& path);

/// Takes the lock of the plan file `path` for subcommand `command` (io/plan_lock.h), waiting up
/// to `wait_seconds` (--wait) for another editor. Prints why it could not (the holder, if
/// known, and how to wait longer) to stderr.
/// @return the lock, held until destroyed, or nullopt: stop with kExitCannotRun.
[[nodiscard]] std::optional<PlanLock> lock_plan(std::string_view command,
                                                const std::filesystem::path& path,
                                                double wait_seconds);

/// Reads and validates the plan for a command that needs a sound plan (build, render): the
/// gate. Prints reading and validation problems to stderr as text, and a summary line when
/// there are errors. With errors the plan is withheld (exit_status kExitPlanErrors) unless
/// `force`, when it is returned anyway and the command goes on at its own risk.
/// @return the plan and the combined report; `plan` empty means stop with `exit_status`.
[[nodiscard]] LoadedPlan load_valid_plan(std::string_view command, const std::filesystem::path& path,
                                         bool force);

/// @return true when `stream` (stdout or stderr) is a terminal and NO_COLOR is not set.
[[nodiscard]] bool use_colour(std::FILE* stream);

}  // namespace roomcad::cli
