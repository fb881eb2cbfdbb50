// set_field: one field of one object from text, type-checked against a table of each kind's
// fields (the same names as the plan format).
#include <fmt/format.h>

#include <algorithm>
#include <variant>
#include <vector>

#include "modeling/build_model.h"
#include "modeling/detail/plan_objects.h"
#include "modeling/nearest_name.h"
#include "modeling/plan_edit.h"
#include "modeling/value_text.h"

namespace roomcad {
namespace {

using Target = std::variant<double*, Point2*, Vec3*, Color*, std::string*, OpeningType*, Hinge*,
                            Swing*, LightType*, Projection*, std::array<std::int64_t, 2>*>;

struct Field {
  std::string_view name;
  Target target;
};

std::vector<Field> fields_of(Wall& w) {
  return {{"id", &w.id},           {"from", &w.from},     {"to", &w.to}, {"thickness", &w.thickness},
          {"height", &w.height},   {"base", &w.base},     {"color", &w.color}};
}
std::vector<Field> fields_of(Opening& o) {
  return {{"id", &o.id},         {"type", &o.type},     {"wall", &o.wall},
          {"offset", &o.offset}, {"width", &o.width},   {"height", &o.height},
          {"sill", &o.sill},     {"hinge", &o.hinge},   {"swing", &o.swing}};
}
std::vector<Field> fields_of(Light& l) {
  return {{"id", &l.id}, {"type", &l.type}, {"direction", &l.direction},
          {"intensity", &l.intensity}, {"ambient", &l.ambient}};
}
std::vector<Field> fields_of(Camera& c) {
  return {{"id", &c.id},         {"projection", &c.projection}, {"eye", &c.eye},
          {"target", &c.target}, {"up", &c.up},                 {"fov_deg", &c.fov_deg},
          {"view_height", &c.view_height}};
}
std::vector<Field> fields_of(Site& s) {
  return {{"origin", &s.origin},         {"cells", &s.cells},         {"cell_size", &s.cell_size},
          {"max_height", &s.max_height}, {"tolerance", &s.tolerance}, {"floor_color", &s.floor_color}};
}

/// Stores `value` in `out` if it has a value. @return whether it had.
template <class T>
bool store(T* out, const std::optional<T>& value) {
  if (value) *out = *value;
  return value.has_value();
}

bool assign(double* out, std::string_view text) { return store(out, parse_number(text)); }
bool assign(Point2* out, std::string_view text) { return store(out, parse_point2(text)); }
bool assign(Vec3* out, std::string_view text) { return store(out, parse_vec3(text)); }
bool assign(Color* out, std::string_view text) { return store(out, parse_color(text)); }
bool assign(OpeningType* out, std::string_view text) { return store(out, parse_opening_type(text)); }
bool assign(Hinge* out, std::string_view text) { return store(out, parse_hinge(text)); }
bool assign(Swing* out, std::string_view text) { return store(out, parse_swing(text)); }
bool assign(LightType* out, std::string_view text) { return store(out, parse_light_type(text)); }
bool assign(Projection* out, std::string_view text) { return store(out, parse_projection(text)); }
bool assign(std::array<std::int64_t, 2>* out, std::string_view text) {
  return store(out, parse_cells(text));
}
bool assign(std::string* out, std::string_view text) {
  if (text.empty()) return false;
  *out = text;
  return true;
}

std::string_view expected(double*) { return "a finite number"; }
std::string_view expected(Point2*) { return "a point x,y"; }
std::string_view expected(Vec3*) { return "a vector x,y,z"; }
std::string_view expected(Color*) { return "a colour #rrggbb"; }
std::string_view expected(OpeningType*) { return "door or window"; }
std::string_view expected(Hinge*) { return "left or right"; }
std::string_view expected(Swing*) { return "in or out"; }
std::string_view expected(LightType*) { return "directional"; }
std::string_view expected(Projection*) { return "perspective or orthographic"; }
std::string_view expected(std::array<std::int64_t, 2>*) { return "two integers nx,ny"; }
std::string_view expected(std::string*) { return "a non-empty id"; }

/// @return " (did you mean 'x'?)" for a near name, else " (fields: a, b, ...)".
std::string suggestion(const std::vector<Field>& fields, std::string_view key) {
  std::vector<std::string_view> names;
  for (const Field& f : fields) names.push_back(f.name);
  if (const auto nearest = nearest_name(key, names))
    return fmt::format(" (did you mean '{}'?)", *nearest);
  return fmt::format(" (fields: {})", fmt::join(names, ", "));
}

/// Who is edited, for messages: the command ("set") and the object ("wall 'w1'").
struct Subject {
  std::string_view verb;
  std::string what;
};

/// Sets `key` of an object whose fields are `fields`.
void set_in(const std::vector<Field>& fields, const Subject& subject, std::string_view key,
            std::string_view value) {
  const auto field = std::find_if(fields.begin(), fields.end(),
                                  [&](const Field& f) { return f.name == key; });
  if (field == fields.end())
    throw PreconditionError(fmt::format("{}: {} has no field '{}'{}", subject.verb,
                                        subject.what, key, suggestion(fields, key)));
  std::visit(
      [&](auto* target) {
        if (!assign(target, value))
          throw PreconditionError(fmt::format("{}: {} field '{}' wants {}, got '{}'",
                                              subject.verb, subject.what, key,
                                              expected(target), value));
      },
      field->target);
}

/// Renames an object (and a wall's openings' references). @return the ids changed.
std::vector<std::string> rename(Plan& plan, detail::ObjectRef ref, std::string_view new_id,
                                std::string_view verb) {
  std::string& id = detail::id_of(plan, ref);
  if (new_id.empty())
    throw PreconditionError(fmt::format("{}: {} '{}' field 'id' wants a non-empty id, got ''",
                                        verb, detail::kind_name(plan, ref), id));
  if (new_id == id) return {};
  detail::require_unused_id(plan, new_id, verb);
  std::vector<std::string> changed{std::string(new_id)};
  if (ref.kind == detail::ObjectKind::wall) {
    for (Opening& o : plan.openings) {
      if (o.wall != id) continue;
      o.wall = new_id;
      changed.push_back(o.id);
    }
  }
  id = new_id;
  return changed;
}

/// Sets a field of one object (or the site). @return whether it changed.
template <class Object>
bool set_field_of(Object& object, const Subject& subject, std::string_view key,
                  std::string_view value) {
  const Object old = object;
  set_in(fields_of(object), subject, key, value);
  return object != old;
}

/// Sets a field of the object `ref`. @return whether the object changed.
bool set_object_field(Plan& plan, detail::ObjectRef ref, std::string_view key,
                      std::string_view value, std::string_view verb) {
  const Subject what{verb, fmt::format("{} '{}'", detail::kind_name(plan, ref), detail::id_of(plan, ref))};
  switch (ref.kind) {
    case detail::ObjectKind::wall: return set_field_of(plan.walls[ref.index], what, key, value);
    case detail::ObjectKind::opening:
      return set_field_of(plan.openings[ref.index], what, key, value);
    case detail::ObjectKind::light: return set_field_of(plan.lights[ref.index], what, key, value);
    case detail::ObjectKind::camera: break;
  }
  return set_field_of(plan.cameras[ref.index], what, key, value);
}

}  // namespace

EditSummary set_field(Plan& plan, std::string_view id, std::string_view key,
                      std::string_view value, std::string_view verb) {
  EditSummary summary;
  const auto ref = detail::find_object(plan, id);
  if (!ref && id == "site") {
    if (set_field_of(plan.site, Subject{verb, "the site"}, key, value)) summary.changed.push_back("site");
    return summary;
  }
  const detail::ObjectRef object = detail::require_object(plan, id, verb);
  if (key == "id") {
    summary.changed = rename(plan, object, value, verb);
  } else if (set_object_field(plan, object, key, value, verb)) {
    summary.changed.push_back(std::string(id));
  }
  return summary;
}

std::vector<std::string_view> field_names(std::string_view kind) {
  std::vector<Field> fields;
  Wall wall;
  Opening opening;
  Light light;
  Camera camera;
  Site site;
  if (kind == "wall") fields = fields_of(wall);
  if (kind == "door" || kind == "window") fields = fields_of(opening);
  if (kind == "light") fields = fields_of(light);
  if (kind == "camera") fields = fields_of(camera);
  if (kind == "site") fields = fields_of(site);
  std::vector<std::string_view> names;
  for (const Field& f : fields) names.push_back(f.name);
  return names;
}

}  // namespace roomcad
