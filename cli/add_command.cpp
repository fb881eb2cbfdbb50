// roomcad add PLAN KIND [--id ID] [--<field> VALUE ...]: adds a level, wall, door, window, slab,
// light or camera. Its options are the fields of the plan format, from the field tables
// (modeling/plan_fields.h): --from, --thickness, --fov-deg, ...; each type-checked by
// modeling's set_field; ids are generated when --id is not given.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cli/command.h"
#include "cli/edit_session.h"
#include "modeling/plan_edit.h"
#include "modeling/plan_fields.h"
#include "modeling/value_text.h"

namespace roomcad::cli {
namespace {

const std::vector<std::string> kKinds{"level", "wall", "door", "window", "slab", "light", "camera"};

struct AddArgs {
  std::string path;
  std::string kind;
  std::string id;
  std::vector<std::pair<std::string, CLI::Option*>> fields;  ///< field key, its option
  EditFlags flags;
  std::vector<std::string> values;  ///< storage for the field options, one per field
};

/// @return the fields --options may set for `kind` (all but id and the kind itself).
std::vector<std::string_view> settable_fields(std::string_view kind) {
  std::vector<std::string_view> names = field_names(kind);
  std::erase_if(names, [](std::string_view n) { return n == "id" || n == "type"; });
  return names;
}

std::string option_name(std::string_view key) {
  std::string name = fmt::format("--{}", key);
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

/// Calls visit(Object{}) with a default object of the kind ("door" and "window": an Opening).
template <class Visit>
decltype(auto) with_kind(std::string_view kind, Visit&& visit) {
  if (kind == "level") return visit(Level{});
  if (kind == "wall") return visit(Wall{});
  if (kind == "door" || kind == "window") return visit(Opening{});
  if (kind == "slab") return visit(Slab{});
  if (kind == "light") return visit(Light{});
  return visit(Camera{});
}

/// The fields a kind cannot do without (the others have the format's defaults), but its id.
std::vector<std::string_view> required_fields(std::string_view kind) {
  return with_kind(kind, [](const auto& object) {
    std::vector<std::string_view> names;
    for (const auto& f : fields_of<std::decay_t<decltype(object)>>())
      if (f.presence == Presence::required && f.name != "id") names.push_back(f.name);
    return names;
  });
}

/// @return the given field options as (key, value), checked against the kind.
std::vector<std::pair<std::string, std::string>> given_fields(const AddArgs& args) {
  const std::vector<std::string_view> allowed = settable_fields(args.kind);
  std::vector<std::pair<std::string, std::string>> given;
  for (std::size_t i = 0; i < args.fields.size(); ++i) {
    const auto& [key, option] = args.fields[i];
    if (option->count() == 0) continue;
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw_usage_error(fmt::format("{} does not apply to a {} (it takes: {})",
                                              option_name(key), args.kind, fmt::join(allowed, ", ")));
    given.emplace_back(key, args.values[i]);
  }
  for (const std::string_view key : required_fields(args.kind)) {
    if (std::none_of(given.begin(), given.end(), [&](const auto& g) { return g.first == key; }))
      throw_usage_error(fmt::format("add {} needs {}", args.kind, option_name(key)));
  }
  return given;
}

/// Builds the object in a scratch plan (so set_field type-checks every value), then takes it.
template <class Object>
Object build(std::vector<Object> Plan::*list, Object object, const std::string& id,
             const std::vector<std::pair<std::string, std::string>>& given) {
  Plan scratch;
  object.id = id.empty() ? "new" : id;
  (scratch.*list).push_back(std::move(object));
  for (const auto& [key, value] : given) set_field(scratch, (scratch.*list)[0].id, key, value, "add");
  Object built = std::move((scratch.*list)[0]);
  built.id = id;  // empty: add_* generates one
  return built;
}

EditSummary add_object(Plan& plan, const AddArgs& args,
                       const std::vector<std::pair<std::string, std::string>>& given) {
  if (args.kind == "level") return add_level(plan, build(&Plan::levels, Level{}, args.id, given));
  if (args.kind == "wall") return add_wall(plan, build(&Plan::walls, Wall{}, args.id, given));
  if (args.kind == "slab") return add_slab(plan, build(&Plan::slabs, Slab{}, args.id, given));
  if (args.kind == "light") return add_light(plan, build(&Plan::lights, Light{}, args.id, given));
  if (args.kind == "camera")
    return add_camera(plan, build(&Plan::cameras, Camera{}, args.id, given));
  const Opening base = default_opening(*parse_enum<OpeningType>(args.kind));
  return add_opening(plan, build(&Plan::openings, base, args.id, given));
}

/// "level: floor to floor, metres; wall: metres (at from); ..." help, from the field tables.
std::string field_help(std::string_view key) {
  std::vector<std::string> uses;
  for (const std::string& kind : kKinds) {
    if (kind == "window") continue;  // a door's fields
    with_kind(kind, [&](const auto& object) {
      if (const auto* f = find_field<std::decay_t<decltype(object)>>(key))
        uses.push_back(fmt::format("{}{}: {}", kind, kind == "door" ? "/window" : "", f->hint));
    });
  }
  return fmt::format("{}", fmt::join(uses, "; "));
}

}  // namespace

void add_add_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<AddArgs>();
  CLI::App* app =
      root.add_subcommand("add", "Add a level, wall, door, window, slab, light or camera to a plan");
  app->footer(
      "Examples:\n"
      "  roomcad add plan.json wall --from 1,1 --to 11,1 --thickness 0.2\n"
      "  roomcad add plan.json door --wall south --offset 1.5 --width 0.9 --hinge right\n"
      "  roomcad add plan.json window --id w3 --wall north --offset 4 --sill 1.0\n"
      "  roomcad add plan.json light --direction -0.4,0.5,-1 --ambient 0.3\n"
      "  roomcad add plan.json camera --eye 16,-9,10 --target 6,4,1\n"
      "  roomcad add plan.json level --id first --elevation 3 --height 2.6\n"
      "  roomcad add plan.json slab --level first --outline \"0,0;6,0;6,4;0,4\"\n"
      "Ids are generated (wall-1, door-2, ...) unless --id is given. The edited plan is\n"
      "validated: an edit that introduces errors is refused (exit 1, file untouched)\n"
      "unless --force.");
  app->add_option("PLAN", args->path, "plan file to edit")->required();
  app->add_option("KIND", args->kind, "level, wall, door, window, slab, light or camera")
      ->required()
      ->check(CLI::IsMember(kKinds));
  app->add_option("--id", args->id, "id of the new object (default: generated, e.g. wall-3)");
  std::vector<std::string> keys;
  for (const std::string& kind : kKinds)
    for (const std::string_view key : settable_fields(kind))
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.emplace_back(key);
  args->values.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    args->fields.emplace_back(keys[i], app->add_option(option_name(keys[i]), args->values[i],
                                                       field_help(keys[i])));
  add_edit_flags(*app, args->flags);
  commands.push_back({app, [args] {
                        const auto given = given_fields(*args);
                        return run_edit("add", args->path, args->flags,
                                        [&](Plan& plan) { return add_object(plan, *args, given); });
                      }});
}

}  // namespace roomcad::cli
