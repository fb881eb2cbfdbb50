// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the plan a command works on, with its problems printed the same way by every command.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

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

/// How a command shows a plan's findings on stderr: every one (the reading commands: validate
/// lists them itself, info, fmt, view), or one line that counts them, names their codes and
/// points at `roomcad validate` (build, render, draw and the edits, unless --verbose).
enum class Findings { listed, counted };

/// Adds `--verbose` to a command that counts findings: with it, they are listed.
inline CLI::Option* add_verbose_flag(CLI::App& app, bool& verbose) {
  return app.add_flag("--verbose", verbose,
                      "print every finding of the plan (without it, one line counts them; "
                      "`roomcad validate PLAN` lists them)");
}

/// @return how a command given --verbose or not shows findings.
[[nodiscard]] inline Findings findings_for(bool verbose) {
  return verbose ? Findings::listed : Findings::counted;
}

// Each function below has printed its problems to stderr when it returns; a failure's code
// gives the command's exit status (exit_status_of): 2 for a file that cannot be read (missing,
// a directory, no permission) or a lock not taken, 1 for a plan with errors.

/// Reads the plan file `path` for subcommand `command`. Prints its findings, warnings too, to
/// stderr as `findings` says: listed, as text (coloured when stderr is a terminal) and one
/// summary line if there were errors; counted, one line if there were any.
/// @return the plan, or why there is none: the file's reading error, or the plan's first
///         error.
[[nodiscard]] Result<LoadedPlan> load_plan(std::string_view command,
                                           const std::filesystem::path& path,
                                           Findings findings = Findings::listed);

/// Takes the lock of the plan file `path` for subcommand `command` (io/plan_lock.h), waiting up
/// to `wait_seconds` (--wait) for another editor. Prints why it could not (the holder, if
/// known, and how to wait longer) to stderr.
/// @return the lock, held until destroyed, or its lock_timeout or I/O error.
[[nodiscard]] Result<PlanLock> lock_plan(std::string_view command,
                                         const std::filesystem::path& path, double wait_seconds);

/// Reads and validates the plan for a command that needs a sound plan (build, render): the
/// gate. Prints reading and validation findings to stderr as `findings` says, with a summary
/// line when there are errors (counted: one line whenever there are findings). With errors the plan
/// is withheld (the first error is returned) unless `force`, when it is returned anyway and the
/// command goes on at its own risk.
/// @return the plan and the combined report, or why the command stops.
[[nodiscard]] Result<LoadedPlan> load_valid_plan(std::string_view command,
                                                 const std::filesystem::path& path, bool force,
                                                 Findings findings);

/// @return true when `stream` (stdout or stderr) is a terminal and NO_COLOR is not set.
[[nodiscard]] bool use_colour(std::FILE* stream);

}  // namespace roomcad::cli
