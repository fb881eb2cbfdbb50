// Adding and removing objects; ids. Transforms are in plan_transform_edit.cpp, fields in
// plan_set_field.cpp.
#include "modeling/plan_edit.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "modeling/build_model.h"
#include "modeling/detail/plan_objects.h"

namespace roomcad {
namespace {

/// Gives `id` a generated value when empty, else checks it is free; @return the final id.
std::string claim_id(const Plan& plan, std::string id, std::string_view prefix) {
  if (id.empty()) return generate_id(plan, prefix);
  detail::require_unused_id(plan, id, "add");
  return id;
}

/// Appends `object` (id claimed) to `objects`; @return the summary of an addition.
template <class Object>
EditSummary append_object(const Plan& plan, std::vector<Object>& objects, Object object,
                          std::string_view prefix) {
  object.id = claim_id(plan, std::move(object.id), prefix);
  EditSummary summary;
  summary.added.push_back(object.id);
  objects.push_back(std::move(object));
  return summary;
}

}  // namespace

std::optional<std::string_view> object_kind(const Plan& plan, std::string_view id) {
  const auto ref = detail::find_object(plan, id);
  if (!ref) return std::nullopt;
  return detail::kind_name(plan, *ref);
}

std::string generate_id(const Plan& plan, std::string_view prefix) {
  for (std::size_t n = 1;; ++n) {
    std::string id = fmt::format("{}-{}", prefix, n);
    if (!detail::find_object(plan, id)) return id;
  }
}

std::vector<std::string> hosted_openings(const Plan& plan, std::string_view wall_id) {
  std::vector<std::string> ids;
  for (const Opening& o : plan.openings)
    if (o.wall == wall_id) ids.push_back(o.id);
  return ids;
}

Opening default_opening(OpeningType type) {
  const OpeningDefaults d = opening_defaults(type);
  Opening opening;
  opening.type = type;
  opening.width = d.width;
  opening.height = d.height;
  opening.sill = d.sill;
  return opening;
}

EditSummary add_wall(Plan& plan, Wall wall) {
  return append_object(plan, plan.walls, std::move(wall), "wall");
}

EditSummary add_opening(Plan& plan, Opening opening) {
  if (!find_wall(plan, opening.wall))
    throw PreconditionError(fmt::format("add: {} '{}' names wall '{}', and the plan has no such wall",
                                        to_string(opening.type), opening.id, opening.wall));
  const std::string_view prefix = to_string(opening.type);
  return append_object(plan, plan.openings, std::move(opening), prefix);
}

EditSummary add_light(Plan& plan, Light light) {
  return append_object(plan, plan.lights, std::move(light), "light");
}

EditSummary add_camera(Plan& plan, Camera camera) {
  return append_object(plan, plan.cameras, std::move(camera), "camera");
}

EditSummary remove_object(Plan& plan, std::string_view id, const RemoveOptions& options) {
  const detail::ObjectRef ref = detail::require_object(plan, id, "rm");
  EditSummary summary;
  if (ref.kind == detail::ObjectKind::wall) {
    std::vector<std::string> hosted = hosted_openings(plan, id);
    if (!hosted.empty() && !options.cascade)
      throw PreconditionError(fmt::format(
          "rm: wall '{}' has openings ({}); remove them first or use --cascade", id,
          fmt::join(hosted, ", ")));
    std::erase_if(plan.openings, [&](const Opening& o) { return o.wall == id; });
    summary.removed = std::move(hosted);
  }
  summary.removed.insert(summary.removed.begin(), std::string(id));
  switch (ref.kind) {
    case detail::ObjectKind::wall: plan.walls.erase(plan.walls.begin() + ref.index); break;
    case detail::ObjectKind::opening: plan.openings.erase(plan.openings.begin() + ref.index); break;
    case detail::ObjectKind::light: plan.lights.erase(plan.lights.begin() + ref.index); break;
    case detail::ObjectKind::camera: plan.cameras.erase(plan.cameras.begin() + ref.index); break;
  }
  return summary;
}

}  // namespace roomcad
