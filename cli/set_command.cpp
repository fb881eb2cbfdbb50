// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad set PLAN ID key=value ...: sets fields of one object (or of the site, ID "site"),
// each value type-checked against the plan format.
#include <fmt/format.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "cli/command.h"
#include "cli/edit_session.h"
#include "plan/plan_edit.h"

namespace roomcad::cli {
namespace {

struct SetArgs {
  std::string path;
  std::string id;
  std::vector<std::string> assignments;
  EditFlags flags;
};

/// Applies each key=value in order; @return the union of what changed.
Result<EditSummary> set_all(Plan& plan, const SetArgs& args) {
  EditSummary summary;
  std::string id = args.id;
  for (const std::string& assignment : args.assignments) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
      return Result<EditSummary>::failure(
          Code::usage_error, fmt::format("'{}' is not key=value (e.g. thickness=0.3)", assignment));
    const std::string key = assignment.substr(0, eq);
    const std::string value = assignment.substr(eq + 1);
    Result<EditSummary> set = set_field(plan, id, key, value);
    if (!set) return set.error();
    for (std::string& changed : set->changed)
      if (std::find(summary.changed.begin(), summary.changed.end(), changed) ==
          summary.changed.end())
        summary.changed.push_back(std::move(changed));
    if (key == "id") id = value;  // later assignments address the renamed object
  }
  return summary;
}

}  // namespace

void add_set_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<SetArgs>();
  CLI::App* app = root.add_subcommand("set", "Set fields of an object (or of the site)");
  app->footer(
      "Examples:\n"
      "  roomcad set plan.json south thickness=0.3 color=#a0a0a0\n"
      "  roomcad set plan.json win1 sill=1.0 width=1.2\n"
      "  roomcad set plan.json view projection=orthographic view_height=12\n"
      "  roomcad set plan.json site cells=14,10\n"
      "Keys are the plan format's field names; points are x,y and vectors x,y,z. Renaming a\n"
      "wall (id=...) renames its openings' references. The edited plan is validated: an edit\n"
      "that introduces errors is refused (exit 1, file untouched) unless --force.");
  app->add_option("PLAN", args->path, "plan file to edit")->required();
  app->add_option("ID", args->id, "id of the object, or 'site'")->required();
  app->add_option("ASSIGNMENTS", args->assignments, "key=value, one or more")->required();
  add_edit_flags(*app, args->flags);
  commands.push_back({app, [args] {
                        return run_edit("set", args->path, args->flags,
                                        [&](Plan& plan) { return set_all(plan, *args); });
                      }});
}

}  // namespace roomcad::cli
