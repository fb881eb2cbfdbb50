// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad: validated, exact 3D models and pictures from room plans. Every subcommand but
// `view` runs here; `roomcad view` runs the window's own program, roomcad-view (cli/
// window_program.h), so that no other command loads the window's libraries.
#include "cli/command.h"
#include "cli/window_program.h"

int main(int argc, char** argv) {
  using namespace roomcad::cli;
  if (is_window_command(argc, argv)) return run_window_program(argc, argv);
  CLI::App app{
      "roomcad: validate room plans, build exact 3D models of them, and draw and render them.\n"
      "Plans are JSON files (see the plan format). Exit status: 0 success, 1 the plan has\n"
      "errors, 2 the command could not run.",
      "roomcad"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "roomcad 0.1.0");
  Commands commands;
  add_info_command(app, commands);
  add_fmt_command(app, commands);
  add_validate_command(app, commands);
  add_repair_command(app, commands);
  add_report_command(app, commands);
  add_surface_command(app, commands);
  add_draw_command(app, commands);
  add_import_command(app, commands);
  add_build_command(app, commands);
  add_add_command(app, commands);
  add_rm_command(app, commands);
  add_transform_commands(app, commands);
  add_set_command(app, commands);
  add_render_command(app, commands);
  add_sun_command(app, commands);
  add_shadow_study_command(app, commands);
  add_insolation_command(app, commands);
  add_window_command_entry(app);
  return run_command_line(app, commands, argc, argv);
}
