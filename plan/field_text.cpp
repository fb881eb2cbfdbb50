// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/field_text.h"

#include <fmt/format.h>

namespace roomcad::field_text_detail {
namespace {

/// Stores `value` in `out` if it has one. @return whether it had.
template <class T>
bool store(T& out, std::optional<T> value) {
  if (value) out = std::move(*value);
  return value.has_value();
}

}  // namespace

bool parse_value(std::string_view text, double& out) { return store(out, parse_number(text)); }
bool parse_value(std::string_view text, std::optional<double>& out) {
  const auto x = parse_number(text);
  if (x) out = *x;
  return x.has_value();
}
bool parse_value(std::string_view text, Point2& out) { return store(out, parse_point2(text)); }
bool parse_value(std::string_view text, Vec3& out) { return store(out, parse_vec3(text)); }
bool parse_value(std::string_view text, Color& out) { return store(out, parse_color(text)); }
bool parse_value(std::string_view text, std::string& out) {
  if (text.empty()) return false;
  out = text;
  return true;
}
bool parse_value(std::string_view text, std::array<std::int64_t, 2>& out) {
  return store(out, parse_cells(text));
}
bool parse_value(std::string_view text, Polygon& out) { return store(out, parse_polygon(text)); }
bool parse_value(std::string_view text, std::vector<Polygon>& out) {
  return store(out, parse_polygons(text));
}
/// "latitude,longitude" or "latitude,longitude,utc_offset".
bool parse_value(std::string_view text, std::optional<GeoLocation>& out) {
  GeoLocation location = out.value_or(GeoLocation{});
  if (const auto three = parse_vec3(text))
    location.latitude = three->x, location.longitude = three->y, location.utc_offset = three->z;
  else if (const auto two = parse_point2(text))
    location.latitude = two->x, location.longitude = two->y;
  else return false;
  out = std::move(location);
  return true;
}

std::string value_text(double value) { return format_number(value); }
std::string value_text(const std::optional<double>& value) {
  return value ? format_number(*value) : std::string(kNoValue);
}
std::string value_text(Point2 value) { return format_point2(value); }
std::string value_text(Vec3 value) { return format_vec3(value); }
std::string value_text(Color value) { return to_string(value); }
std::string value_text(const std::string& value) { return value; }
std::string value_text(const std::array<std::int64_t, 2>& value) {
  return fmt::format("{},{}", value[0], value[1]);
}
std::string value_text(const Polygon& value) { return format_polygon(value); }
std::string value_text(const std::vector<Polygon>& value) { return format_polygons(value); }
std::string value_text(const std::optional<GeoLocation>& value) {
  if (!value) return std::string(kNoValue);
  return format_vec3({value->latitude, value->longitude, value->utc_offset});
}

std::string wrong_value_message(std::string_view verb, std::string_view object,
                                std::string_view field, std::string_view hint,
                                std::string_view text) {
  return fmt::format("{}: {} field '{}' wants {}, got '{}'", verb, object, field, hint, text);
}

}  // namespace roomcad::field_text_detail
