#include "modeling/detail/plan_objects.h"

#include <fmt/format.h>

#include <vector>

#include "modeling/build_model.h"

namespace roomcad::detail {
namespace {

/// @return the index of the first element whose id is `id`, or nullopt.
template <class Object>
std::optional<std::size_t> index_of(const std::vector<Object>& objects, std::string_view id) {
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (objects[i].id == id) return i;
  return std::nullopt;
}

/// @return up to `most` ids of the plan, comma separated, for "did you mean" style messages.
std::string some_ids(const Plan& plan, std::size_t most) {
  std::vector<std::string_view> ids;
  for (const Wall& w : plan.walls) ids.push_back(w.id);
  for (const Opening& o : plan.openings) ids.push_back(o.id);
  for (const Light& l : plan.lights) ids.push_back(l.id);
  for (const Camera& c : plan.cameras) ids.push_back(c.id);
  if (ids.empty()) return "the plan has no objects";
  const bool cut = ids.size() > most;
  if (cut) ids.resize(most);
  return fmt::format("ids: {}{}", fmt::join(ids, ", "), cut ? ", ..." : "");
}

}  // namespace

std::optional<ObjectRef> find_object(const Plan& plan, std::string_view id) {
  if (const auto i = index_of(plan.walls, id)) return ObjectRef{ObjectKind::wall, *i};
  if (const auto i = index_of(plan.openings, id)) return ObjectRef{ObjectKind::opening, *i};
  if (const auto i = index_of(plan.lights, id)) return ObjectRef{ObjectKind::light, *i};
  if (const auto i = index_of(plan.cameras, id)) return ObjectRef{ObjectKind::camera, *i};
  return std::nullopt;
}

ObjectRef require_object(const Plan& plan, std::string_view id, std::string_view verb) {
  if (const auto ref = find_object(plan, id)) return *ref;
  throw PreconditionError(
      fmt::format("{}: no object has id '{}' ({})", verb, id, some_ids(plan, 8)));
}

std::string_view kind_name(const Plan& plan, ObjectRef ref) {
  switch (ref.kind) {
    case ObjectKind::wall: return "wall";
    case ObjectKind::opening: return to_string(plan.openings[ref.index].type);
    case ObjectKind::light: return "light";
    case ObjectKind::camera: return "camera";
  }
  return "object";
}

std::string& id_of(Plan& plan, ObjectRef ref) {
  switch (ref.kind) {
    case ObjectKind::wall: return plan.walls[ref.index].id;
    case ObjectKind::opening: return plan.openings[ref.index].id;
    case ObjectKind::light: return plan.lights[ref.index].id;
    case ObjectKind::camera: break;
  }
  return plan.cameras[ref.index].id;
}

void require_unused_id(const Plan& plan, std::string_view id, std::string_view verb) {
  if (const auto ref = find_object(plan, id))
    throw PreconditionError(fmt::format("{}: id '{}' is already used by {} '{}'", verb, id,
                                        kind_name(plan, *ref), id));
}

}  // namespace roomcad::detail
