// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad rm PLAN ID [--cascade]: removes an object; a wall that holds openings only with
// --cascade (which removes them too).
#include <fmt/format.h>

#include <memory>

#include "cli/command.h"
#include "cli/edit_session.h"
#include "plan/plan_edit.h"

namespace roomcad::cli {
namespace {

struct RmArgs {
  std::string path;
  std::string id;
  bool cascade = false;
  EditFlags flags;
};

}  // namespace

void add_rm_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<RmArgs>();
  CLI::App* app = root.add_subcommand(
      "rm", "Remove an object (level, wall, door, window, slab, light, camera)");
  app->footer(
      "Examples:\n"
      "  roomcad rm plan.json win1\n"
      "  roomcad rm plan.json south --cascade   # the wall and its doors and windows\n"
      "A wall with openings, or a level with walls or slabs on it, is refused (exit 1, file\n"
      "untouched) unless --cascade, which removes them with it.");
  app->add_option("PLAN", args->path, "plan file to edit")->required();
  app->add_option("ID", args->id, "id of the object to remove")->required();
  app->add_flag("--cascade", args->cascade,
                "removing a wall also removes its openings; a level, its walls and slabs");
  add_edit_flags(*app, args->flags);
  commands.push_back({app, [args] {
                        return run_edit("rm", args->path, args->flags, [&](Plan& plan) {
                          return remove_object(plan, args->id, {.cascade = args->cascade});
                        });
                      }});
}

}  // namespace roomcad::cli
