// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad-view: the window of `roomcad view` (cli/window_program.h), which roomcad runs with
// its own arguments ("view PLAN ..."). The one executable that links the window's libraries.
#include "cli/command.h"

int main(int argc, char** argv) {
  using namespace roomcad::cli;
  CLI::App app{"roomcad view: the window on a plan (run as `roomcad view`).", "roomcad"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "roomcad 0.1.0");
  Commands commands;
  add_view_command(app, commands);
  return run_command_line(app, commands, argc, argv);
}
