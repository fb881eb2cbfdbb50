#include "modeling/value_text.h"

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace roomcad {
namespace {

std::string_view trim(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

/// Splits on commas; @return the trimmed parts, or an empty vector unless there are `count`.
std::vector<std::string_view> split_exactly(std::string_view text, std::size_t count) {
  std::vector<std::string_view> parts;
  while (true) {
    const std::size_t comma = text.find(',');
    parts.push_back(trim(text.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  if (parts.size() != count) parts.clear();
  return parts;
}

/// @return the enum value whose to_string is `text`, or nullopt.
template <class Enum>
std::optional<Enum> parse_enum(std::string_view text, std::initializer_list<Enum> values) {
  for (const Enum value : values)
    if (to_string(value) == text) return value;
  return std::nullopt;
}

}  // namespace

std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
  text = trim(text);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<Point2> parse_point2(std::string_view text) {
  const auto parts = split_exactly(text, 2);
  if (parts.empty()) return std::nullopt;
  const auto x = parse_number(parts[0]);
  const auto y = parse_number(parts[1]);
  if (!x || !y) return std::nullopt;
  return Point2{*x, *y};
}

std::optional<Vec3> parse_vec3(std::string_view text) {
  const auto parts = split_exactly(text, 3);
  if (parts.empty()) return std::nullopt;
  const auto x = parse_number(parts[0]);
  const auto y = parse_number(parts[1]);
  const auto z = parse_number(parts[2]);
  if (!x || !y || !z) return std::nullopt;
  return Vec3{*x, *y, *z};
}

std::optional<std::array<std::int64_t, 2>> parse_cells(std::string_view text) {
  const auto parts = split_exactly(text, 2);
  if (parts.empty()) return std::nullopt;
  const auto nx = parse_integer(parts[0]);
  const auto ny = parse_integer(parts[1]);
  if (!nx || !ny) return std::nullopt;
  return std::array<std::int64_t, 2>{*nx, *ny};
}

std::optional<OpeningType> parse_opening_type(std::string_view text) {
  return parse_enum(text, {OpeningType::door, OpeningType::window});
}
std::optional<Hinge> parse_hinge(std::string_view text) {
  return parse_enum(text, {Hinge::left, Hinge::right});
}
std::optional<Swing> parse_swing(std::string_view text) {
  return parse_enum(text, {Swing::in, Swing::out});
}
std::optional<LightType> parse_light_type(std::string_view text) {
  return parse_enum(text, {LightType::directional});
}
std::optional<Projection> parse_projection(std::string_view text) {
  return parse_enum(text, {Projection::perspective, Projection::orthographic});
}

}  // namespace roomcad
