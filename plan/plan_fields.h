// SPDX-License-Identifier: GPL-3.0-or-later
// The fields of each kind of plan object, in one table per kind: name, member, unit, check and
// presence. This is the only place a field is spelled. The JSON reader and writer
// (io/plan_json.h), `set` and `add` (plan/plan_edit.h), the value checks
// (validation/validate.h) and the window's property panel all walk these tables, so adding a
// field to the format is one entry here (and its member in plan/plan.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "plan/plan.h"

namespace roomcad {

/// The unit of a number, a point or a vector field: metres are converted from a file's
/// `units` and must lie in the range exact geometry computes in; degrees and plain numbers
/// (intensity, unit-square coordinates) are read as they are.
enum class Unit : std::uint8_t { none, metre, degree };

/// What a value must be beyond its type; validation reports invalid_value otherwise (a number
/// is always finite, an id never empty).
enum class Check : std::uint8_t {
  finite,          ///< any finite number
  positive,        ///< > 0
  non_negative,    ///< >= 0
  level_offset,    ///< a wall's base: >= 0 without a level; on a level any finite number (a
                   ///< wall reaching down through its level's floor), its absolute z >= 0
  unit_interval,   ///< in [0, 1] (ambient)
  non_zero,        ///< a direction other than (0, 0, 0)
  turn,            ///< an arc's extent: 0 < |x| < 360 degrees
  lens,            ///< a camera's fov (perspective: 0 < x < 180 degrees) or view height
                   ///< (orthographic: > 0), checked for the camera's projection only
  positive_cells,  ///< site cells: whole numbers >= 1
  latitude,        ///< in [-90, 90] degrees
  longitude,       ///< in [-180, 180] degrees
  utc_offset,      ///< in [-12, 14] hours
  polygon,         ///< at least 3 corners, simple (checked with the geometry)
  polygons,        ///< each a polygon
  any,             ///< ids, references, colours, enums: their type says it all
};

/// Whether a field must be given, and when it is written.
enum class Presence : std::uint8_t {
  required,  ///< reading a file without it is a parse_error; always written
  optional,  ///< missing: the default; always written (the canonical form writes every field)
  version2,  ///< a version-2 field: missing means absent (empty), written only when present,
             ///< and its presence makes a plan version 2
};

/// A member of an object of type Object, by its type. Enums are listed one by one, so that a
/// visitor gets the enum's own type.
template <class Object>
using Member = std::variant<double Object::*, std::optional<double> Object::*, Point2 Object::*,
                            Vec3 Object::*, Color Object::*, std::string Object::*,
                            std::array<std::int64_t, 2> Object::*, Polygon Object::*,
                            std::vector<Polygon> Object::*, std::optional<GeoLocation> Object::*,
                            OpeningType Object::*, Hinge Object::*, Swing Object::*,
                            LightType Object::*, Projection Object::*>;

/// One field of the format.
template <class Object>
struct Field {
  std::string_view name;  ///< as written in the file, `set` and `add --name`
  Member<Object> member;
  Unit unit = Unit::none;
  Check check = Check::finite;
  Presence presence = Presence::optional;
  double example = 0.0;   ///< a sensible value, for the fix of an invalid_value
  std::string_view hint;  ///< what the value is, for messages and --help ("x,y in metres")
};

/// The field table of an object type, in the order the canonical writer writes the fields.
/// O(1). Defined for Site, GeoLocation, Level, Wall, Opening, Slab, RoomLabel, Obstruction,
/// Light and Camera.
template <class Object>
[[nodiscard]] std::span<const Field<Object>> fields_of();
template <>
std::span<const Field<Site>> fields_of<Site>();
template <>
std::span<const Field<GeoLocation>> fields_of<GeoLocation>();
template <>
std::span<const Field<Level>> fields_of<Level>();
template <>
std::span<const Field<Wall>> fields_of<Wall>();
template <>
std::span<const Field<Opening>> fields_of<Opening>();
template <>
std::span<const Field<Slab>> fields_of<Slab>();
template <>
std::span<const Field<RoomLabel>> fields_of<RoomLabel>();
template <>
std::span<const Field<Obstruction>> fields_of<Obstruction>();
template <>
std::span<const Field<Light>> fields_of<Light>();
template <>
std::span<const Field<Camera>> fields_of<Camera>();

/// The keys of a plan document's top level, in the order the writer writes them.
inline constexpr std::array<std::string_view, 12> kTopLevelKeys = {
    "format",   "version", "units",        "site",  "levels", "walls",
    "openings", "slabs",   "obstructions", "rooms", "lights", "cameras"};

/// @return the field named `name`, or nullptr. O(fields).
template <class Object>
[[nodiscard]] const Field<Object>* find_field(std::string_view name) {
  for (const Field<Object>& f : fields_of<Object>())
    if (f.name == name) return &f;
  return nullptr;
}

/// @return the names of a table's fields, in order.
template <class Object>
[[nodiscard]] std::vector<std::string_view> field_names_of() {
  std::vector<std::string_view> names;
  for (const Field<Object>& f : fields_of<Object>()) names.push_back(f.name);
  return names;
}

/// @return whether a version-2 field holds a value in `object` (an optional with a value, a
///         non-empty id, polygon or list). Always true for the other fields.
template <class Object>
[[nodiscard]] bool is_present(const Object& object, const Field<Object>& field) {
  if (field.presence != Presence::version2) return true;
  return std::visit(
      [&](auto member) {
        const auto& value = object.*member;
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::optional<double>> ||
                      std::is_same_v<T, std::optional<GeoLocation>>)
          return value.has_value();
        else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, Polygon> ||
                           std::is_same_v<T, std::vector<Polygon>>)
          return !value.empty();
        else return true;
      },
      field.member);
}

/// @return whether a plan uses anything of version 2 (levels, slabs, or a version-2 field of
///         any object): the version the writer writes. O(n).
[[nodiscard]] bool uses_version2(const Plan& plan);

}  // namespace roomcad
