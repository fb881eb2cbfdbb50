// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/window_program.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "cli/command.h"

namespace roomcad::cli {

bool is_window_command(int argc, char** argv) {
  return argc >= 2 && std::string_view(argv[1]) == kWindowCommand;
}

int run_window_program(int argc, char** argv) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path program = self.parent_path() / kWindowProgram;
  if (!error) {
    std::vector<char*> args(argv, argv + argc + 1);  // argv[argc] is the null pointer
    std::string name = program.string();
    args[0] = name.data();
    ::execv(name.c_str(), args.data());
    error = std::error_code(errno, std::generic_category());
  }
  return report_failure(
      kWindowCommand,
      {Code::io_error, fmt::format("cannot run the window's program {}: {} (it is installed "
                                   "beside roomcad; the other commands need no window)",
                                   program.string(), error.message())});
}

void add_window_command_entry(CLI::App& root) {
  CLI::App* entry = root.add_subcommand(kWindowCommand, kWindowDescription);
  entry->allow_extras();
}

}  // namespace roomcad::cli
