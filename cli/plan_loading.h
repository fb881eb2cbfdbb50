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

/// A plan read for a command.
struct LoadedPlan {
  Plan plan;
  std::string text;  ///< the file's bytes
  Report report;     ///< what reading (and validating, for load_valid_plan) found
};

// Each function below has printed its problems to stderr when it returns; a failure's code
// gives the command's exit status (exit_status_of): 2 for a file that cannot be read (missing,
// a directory, no permission) or a lock not taken, 1 for a plan with errors.

/// Reads the plan file `path` for subcommand `command`. Prints every problem, warnings too, to
/// stderr as text (coloured when stderr is a terminal), then one summary line if there were
/// errors. @return the plan, or why there is none: the file's reading error, or the plan's
///         first error.
[[nodiscard]] Result<LoadedPlan> load_plan(std::string_view command,
                                           const std::filesystem::path& path);

/// Takes the lock of the plan file `path` for subcommand `command` (io/plan_lock.h), waiting up
/// to `wait_seconds` (--wait) for another editor. Prints why it could not (the holder, if
/// known, and how to wait longer) to stderr.
/// @return the lock, held until destroyed, or its lock_timeout or I/O error.
[[nodiscard]] Result<PlanLock> lock_plan(std::string_view command,
                                         const std::filesystem::path& path, double wait_seconds);

/// Reads and validates the plan for a command that needs a sound plan (build, render): the
/// gate. Prints reading and validation problems to stderr as text, and a summary line when
/// there are errors. With errors the plan is withheld (the first error is returned) unless
/// `force`, when it is returned anyway and the command goes on at its own risk.
/// @return the plan and the combined report, or why the command stops.
[[nodiscard]] Result<LoadedPlan> load_valid_plan(std::string_view command,
                                                 const std::filesystem::path& path, bool force);

/// @return true when `stream` (stdout or stderr) is a terminal and NO_COLOR is not set.
[[nodiscard]] bool use_colour(std::FILE* stream);

}  // namespace roomcad::cli
