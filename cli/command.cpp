// SPDX-License-Identifier: GPL-3.0-or-later
// What both executables share (cli/command.h): running the parsed subcommand, reporting
// failures, the --wait option.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "cli/command.h"
#include "io/plan_lock.h"

namespace roomcad::cli {

int run_command_line(CLI::App& app, const Commands& commands, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    return report_usage_error(app, e);
  }
  for (const Command& c : commands) {
    if (!c.app->parsed()) continue;
    try {
      return c.run();
    } catch (const PreconditionError& e) {
      return report_failure(c.app->get_name(), e.error());
    } catch (const std::exception& e) {  // out of memory, or a bug
      return report_failure(c.app->get_name(), {Code::internal, e.what()});
    }
  }
  return kExitCannotRun;
}

int report_failure(std::string_view command, const Error& error) {
  // error[CODE], as findings are printed, so that scripts and tests read the code.
  const std::string code(to_string(error.code));
  const std::string who = command.empty() ? "roomcad" : "roomcad " + std::string(command);
  std::fprintf(stderr, "%s: error[%s]: %s\n", who.c_str(), code.c_str(), error.message.c_str());
  return exit_status_of(error.code);
}

std::chrono::milliseconds wait_duration(double seconds) {
  return std::chrono::milliseconds(std::llround(seconds * 1000.0));
}

CLI::Option* add_wait_option(CLI::App& app, double& seconds, const std::string& what) {
  seconds = std::chrono::duration<double>(kDefaultLockWait).count();
  return app
      .add_option("--wait", seconds,
                  what.empty() ? "seconds to wait for another editor of the plan (another roomcad "
                                 "command, or `roomcad view` saving) to finish before giving up "
                                 "(exit 2)"
                               : what)
      ->type_name("SECONDS")
      ->check(CLI::Range(0.0, 86400.0))
      ->capture_default_str();
}

int report_usage_error(const CLI::App& app, const CLI::ParseError& error) {
  // The deepest subcommand given names the command (its --help is the one to read).
  const CLI::App* command = &app;
  for (bool deeper = true; deeper;) {
    deeper = false;
    for (const CLI::App* sub : command->get_subcommands())
      if (sub->parsed()) command = sub, deeper = true;
  }
  const std::string name = command == &app ? std::string() : command->get_name();
  const int status = report_failure(name, {Code::usage_error, error.what()});
  std::fprintf(stderr, "Run with --help for more information.\n");
  return status;
}

}  // namespace roomcad::cli
