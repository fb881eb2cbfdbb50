// How subcommands plug into the `roomcad` command: each cli/<name>_command.cpp defines one
// add_<name>_command that registers its options on the root app and returns what to run.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace roomcad::cli {

/// Exit statuses of every command (../shared/spec/plan-format.md).
enum ExitStatus : int { kOk = 0, kPlanErrors = 1, kCannotRun = 2 };

/// A registered subcommand and the function that runs it once its options are parsed.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};
using Commands = std::vector<Command>;

/// Adds `--format text|json` (default text) to a command; `what` says what it formats.
inline CLI::Option* add_format_option(CLI::App& app, std::string& format,
                                      const std::string& what = "output format") {
  return app.add_option("--format", format, what + ": text (default) or json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
}

void add_info_command(CLI::App& root, Commands& commands);
void add_fmt_command(CLI::App& root, Commands& commands);
void add_validate_command(CLI::App& root, Commands& commands);
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

}  // namespace roomcad::cli
