// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/value_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
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

std::optional<Polygon> parse_polygon(std::string_view text) {
  Polygon polygon;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const auto p = parse_point2(text.substr(start, end - start));
    if (!p) return std::nullopt;
    polygon.push_back(*p);
    start = end + 1;
  }
  return polygon;
}

std::optional<std::vector<Polygon>> parse_polygons(std::string_view text) {
  std::vector<Polygon> polygons;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('|', start), text.size());
    auto polygon = parse_polygon(text.substr(start, end - start));
    if (!polygon) return std::nullopt;
    polygons.push_back(std::move(*polygon));
    start = end + 1;
  }
  return polygons;
}

std::string format_number(double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x + 0.0).ptr;  // -0 -> 0
  return std::string(buffer, end);
}

std::string format_point2(Point2 p) { return format_number(p.x) + ',' + format_number(p.y); }

std::string format_vec3(Vec3 v) {
  return format_number(v.x) + ',' + format_number(v.y) + ',' + format_number(v.z);
}

std::string format_polygon(const Polygon& polygon) {
  std::string out;
  for (const Point2& p : polygon) {
    if (!out.empty()) out += ';';  // appended, not `";" + ...`: GCC 12 warns (-Wrestrict) on that
    out += format_point2(p);
  }
  return out;
}

std::string format_polygons(const std::vector<Polygon>& polygons) {
  std::string out;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (i) out += '|';
    out += format_polygon(polygons[i]);
  }
  return out;
}

}  // namespace roomcad
