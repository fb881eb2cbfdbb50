// SPDX-License-Identifier: GPL-3.0-or-later
// How subcommands plug into the `roomcad` command: each cli/<name>_command.cpp defines one
// add_<name>_command that registers its options on the root app and returns what to run.
//
// Failing: a command's run function returns its exit status; a step that fails returns an
// Error (Result/Status) which the command hands to report_failure. A PreconditionError of a
// library call (a precondition the command did not check) reaches main, which reports it the
// same way.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/error.h"

namespace roomcad::cli {

/// Prints "roomcad <command>: error[<code>]: <message>" on stderr ("roomcad: ..." when
/// `command` is empty), the code as core/code.h names it.
/// @return the exit status of the error's code (exit_status_of in core/code.h).
int report_failure(std::string_view command, const Error& error);

/// report_failure for a command line CLI11 could not parse (a usage_error naming the deepest
/// subcommand given), then "Run with --help for more information." @return 2.
int report_usage_error(const CLI::App& app, const CLI::ParseError& error);

/// A registered subcommand and the function that runs it once its options are parsed.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};
using Commands = std::vector<Command>;

/// Adds `--wait SECONDS` (default kDefaultLockWait, io/plan_lock.h): how long the command
/// waits for another editor's lock of the plan before it gives up (exit 2, lock_timeout);
/// `what` replaces the help's description.
CLI::Option* add_wait_option(CLI::App& app, double& seconds, const std::string& what = "");

/// @return the --wait value as a duration (rounded to the millisecond).
[[nodiscard]] std::chrono::milliseconds wait_duration(double seconds);

/// Adds `--format text|json` (default text) to a command; `what` says what it formats.
inline CLI::Option* add_format_option(CLI::App& app, std::string& format,
                                      const std::string& what = "output format") {
  return app.add_option("--format", format, what + ": text (default) or json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
}

/// Parses the command line into `app` and runs the subcommand given (its Command), reporting
/// a parse error, a PreconditionError or any other exception as report_failure does.
/// @return the exit status.
int run_command_line(CLI::App& app, const Commands& commands, int argc, char** argv);

void add_info_command(CLI::App& root, Commands& commands);
void add_fmt_command(CLI::App& root, Commands& commands);
void add_validate_command(CLI::App& root, Commands& commands);
void add_repair_command(CLI::App& root, Commands& commands);
void add_report_command(CLI::App& root, Commands& commands);
void add_surface_command(CLI::App& root, Commands& commands);
void add_draw_command(CLI::App& root, Commands& commands);
void add_import_command(CLI::App& root, Commands& commands);
void add_build_command(CLI::App& root, Commands& commands);
void add_add_command(CLI::App& root, Commands& commands);
void add_rm_command(CLI::App& root, Commands& commands);
void add_transform_commands(CLI::App& root, Commands& commands);  ///< move, rotate, scale
void add_set_command(CLI::App& root, Commands& commands);
void add_render_command(CLI::App& root, Commands& commands);
void add_view_command(CLI::App& root, Commands& commands);
void add_sun_command(CLI::App& root, Commands& commands);
void add_shadow_study_command(CLI::App& root, Commands& commands);
void add_insolation_command(CLI::App& root, Commands& commands);

}  // namespace roomcad::cli
