// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad add PLAN KIND [--id ID] [--<field> VALUE ...]: adds a level, wall, door, window, slab,
// room, light or camera. Its options are the fields of the plan format, from the field tables
// (plan/plan_fields.h): --from, --thickness, --fov-deg, ...; each type-checked by
// modeling's set_field; ids are generated when --id is not given.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cli/command.h"
#include "cli/edit_session.h"
#include "plan/plan_add.h"
#include "plan/plan_fields.h"

namespace roomcad::cli {
namespace {

const std::vector<std::string> kKinds(std::begin(kAddableKinds), std::end(kAddableKinds));

struct AddArgs {
  std::string path;
  std::string kind;
  std::string id;
  std::vector<std::pair<std::string, CLI::Option*>> fields;  ///< field key, its option
  EditFlags flags;
  std::vector<std::string> values;  ///< storage for the field options, one per field
};

std::string option_name(std::string_view key) {
  std::string name = fmt::format("--{}", key);
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

/// @return the given field options as (key, value), or a usage_error: checked against the
/// kind, as add_object checks them too, but these messages name the options.
Result<FieldValues> given_fields(const AddArgs& args) {
  const std::vector<std::string_view> allowed = settable_fields(args.kind);
  FieldValues given;
  for (std::size_t i = 0; i < args.fields.size(); ++i) {
    const auto& [key, option] = args.fields[i];
    if (option->count() == 0) continue;
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      return Result<FieldValues>::failure(
          Code::usage_error, fmt::format("{} does not apply to a {} (it takes: {})",
                                         option_name(key), args.kind, fmt::join(allowed, ", ")));
    given.emplace_back(key, args.values[i]);
  }
  for (const std::string_view key : required_fields(args.kind)) {
    if (std::none_of(given.begin(), given.end(), [&](const auto& g) { return g.first == key; }))
      return Result<FieldValues>::failure(
          Code::usage_error, fmt::format("add {} needs {}", args.kind, option_name(key)));
  }
  return given;
}

/// "level: floor to floor, metres; wall: metres (at from); ..." help, from the field tables.
std::string field_help(std::string_view key) {
  std::vector<std::string> uses;
  for (const std::string& kind : kKinds) {
    if (kind == "window") continue;  // a door's fields
    with_default_object(kind, [&](const auto& object) {
      if (const auto* f = find_field<std::decay_t<decltype(object)>>(key))
        uses.push_back(fmt::format("{}{}: {}", kind, kind == "door" ? "/window" : "", f->hint));
    });
  }
  return fmt::format("{}", fmt::join(uses, "; "));
}

}  // namespace

void add_add_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<AddArgs>();
  CLI::App* app = root.add_subcommand("add",
                                      "Add a level, wall, door, window, slab, room (a name for the "
                                      "room around a point), light or camera to a plan");
  app->footer(
      "Examples:\n"
      "  roomcad add plan.json wall --from 1,1 --to 11,1 --thickness 0.2\n"
      "  roomcad add plan.json door --wall south --offset 1.5 --width 0.9 --hinge right\n"
      "  roomcad add plan.json window --id w3 --wall north --offset 4 --sill 1.0\n"
      "  roomcad add plan.json light --direction -0.4,0.5,-1 --ambient 0.3\n"
      "  roomcad add plan.json camera --eye 16,-9,10 --target 6,4,1\n"
      "  roomcad add plan.json level --id first --elevation 3 --height 2.6\n"
      "  roomcad add plan.json slab --level first --outline \"0,0;6,0;6,4;0,4\"\n"
      "  roomcad add plan.json room --at 3,2 --name Kitchen\n"
      "Ids are generated (wall-1, door-2, ...) unless --id is given. The edited plan is\n"
      "validated: an edit that introduces errors is refused (exit 1, file untouched)\n"
      "unless --force.");
  app->add_option("PLAN", args->path, "plan file to edit")->required();
  app->add_option("KIND", args->kind, "level, wall, door, window, slab, room, light or camera")
      ->required()
      ->check(CLI::IsMember(kKinds));
  app->add_option("--id", args->id, "id of the new object (default: generated, e.g. wall-3)");
  std::vector<std::string> keys;
  for (const std::string& kind : kKinds)
    for (const std::string_view key : settable_fields(kind))
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.emplace_back(key);
  args->values.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    args->fields.emplace_back(
        keys[i], app->add_option(option_name(keys[i]), args->values[i], field_help(keys[i])));
  add_edit_flags(*app, args->flags);
  commands.push_back({app, [args] {
                        const Result<FieldValues> given = given_fields(*args);
                        if (!given) return report_failure("add", given.error());
                        return run_edit("add", args->path, args->flags, [&](Plan& plan) {
                          return add_object(plan, args->kind, args->id, *given);
                        });
                      }});
}

}  // namespace roomcad::cli
