// SPDX-License-Identifier: GPL-3.0-or-later
// A field of a plan object as text: what `roomcad set` and `roomcad add` read, and what the
// window's property panel shows, through the field tables (plan/plan_fields.h). The text
// of a value reads back to the same value.
#pragma once

#include <string>
#include <string_view>
#include <type_traits>

#include "core/error.h"
#include "plan/plan_fields.h"
#include "plan/value_text.h"

namespace roomcad {

/// The word that clears a version-2 field (`set w height_at_end=none`).
inline constexpr std::string_view kNoValue = "none";

namespace field_text_detail {

/// Parses one value type; @return whether `text` was one (then `out` is set).
bool parse_value(std::string_view text, double& out);
bool parse_value(std::string_view text, std::optional<double>& out);
bool parse_value(std::string_view text, Point2& out);
bool parse_value(std::string_view text, Vec3& out);
bool parse_value(std::string_view text, Color& out);
bool parse_value(std::string_view text, std::string& out);
bool parse_value(std::string_view text, std::array<std::int64_t, 2>& out);
bool parse_value(std::string_view text, Polygon& out);
bool parse_value(std::string_view text, std::vector<Polygon>& out);
bool parse_value(std::string_view text, std::optional<GeoLocation>& out);
template <class E>
requires std::is_enum_v<E>
bool parse_value(std::string_view text, E& out) {
  const auto value = parse_enum<E>(text);
  if (value) out = *value;
  return value.has_value();
}

std::string value_text(double value);
std::string value_text(const std::optional<double>& value);
std::string value_text(Point2 value);
std::string value_text(Vec3 value);
std::string value_text(Color value);
std::string value_text(const std::string& value);
std::string value_text(const std::array<std::int64_t, 2>& value);
std::string value_text(const Polygon& value);
std::string value_text(const std::vector<Polygon>& value);
std::string value_text(const std::optional<GeoLocation>& value);
template <class E>
requires std::is_enum_v<E> std::string value_text(E value) { return std::string(to_string(value)); }

/// @return "set: wall 'w1' field 'height' wants metres, got 'tall'".
std::string wrong_value_message(std::string_view verb, std::string_view object,
                                std::string_view field, std::string_view hint,
                                std::string_view text);

}  // namespace field_text_detail

/// Sets `field` of `object` from `text` (a version-2 field is cleared by kNoValue). Only the
/// type is checked here; validation judges the value (a negative thickness is set, then
/// reported).
/// @param[in] verb, what  the command and the object, for the message ("set", "wall 'w1'")
/// @return success, or a usage_error naming the object, field, expected form and text; the
///         object is unchanged then.
template <class Object>
Status set_field_text(Object& object, const Field<Object>& field, std::string_view text,
                      std::string_view verb, std::string_view what) {
  using namespace field_text_detail;
  return std::visit(
      [&](auto member) -> Status {
        auto value = object.*member;
        const bool clears = field.presence == Presence::version2 && text == kNoValue;
        if (clears) value = {};
        if (clears || parse_value(text, value)) {
          object.*member = std::move(value);
          return Status::success();
        }
        return Status::failure(Code::usage_error,
                               wrong_value_message(verb, what, field.name, field.hint, text));
      },
      field.member);
}

/// @return the field's value as text that set_field_text reads back (kNoValue for an absent
///         version-2 field).
template <class Object>
std::string field_text(const Object& object, const Field<Object>& field) {
  if (!is_present(object, field)) return std::string(kNoValue);
  return std::visit([&](auto member) { return field_text_detail::value_text(object.*member); },
                    field.member);
}

}  // namespace roomcad
