// SPDX-License-Identifier: GPL-3.0-or-later
// The values of plan fields as text, as typed on the command line (`set`, `add`) and shown in
// the window: strict parsing (a whole string or nothing, never a prefix: "1.5m" is not 1.5;
// never NaN or infinity) and the formatting that reads back to the same value.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "plan/plan.h"

namespace roomcad {

/// @return the finite number `text` spells ("2.5", "-1e-3"), or nullopt.
[[nodiscard]] std::optional<double> parse_number(std::string_view text);

/// @return the integer `text` spells ("12"), or nullopt.
[[nodiscard]] std::optional<std::int64_t> parse_integer(std::string_view text);

/// @return `x,y` as a point (spaces around the numbers allowed), or nullopt.
[[nodiscard]] std::optional<Point2> parse_point2(std::string_view text);

/// @return `x,y,z` as a vector, or nullopt.
[[nodiscard]] std::optional<Vec3> parse_vec3(std::string_view text);

/// @return `nx,ny` as two integers (site cells), or nullopt.
[[nodiscard]] std::optional<std::array<std::int64_t, 2>> parse_cells(std::string_view text);

/// @return the value of an enum of the format whose name (to_string) is `text`, or nullopt.
template <class E>
[[nodiscard]] std::optional<E> parse_enum(std::string_view text) {
  for (const E value : EnumValues<E>::all)
    if (to_string(value) == text) return value;
  return std::nullopt;
}

/// @return `x,y;x,y;...` as a polygon (at least one point), or nullopt.
[[nodiscard]] std::optional<Polygon> parse_polygon(std::string_view text);

/// @return polygons separated by `|` (`x,y;x,y;x,y|x,y;...`), or nullopt.
[[nodiscard]] std::optional<std::vector<Polygon>> parse_polygons(std::string_view text);

/// The same values as text the parsers above read back exactly: numbers as the shortest
/// decimal that reads back to the same double (no "-0").
[[nodiscard]] std::string format_number(double x);
[[nodiscard]] std::string format_point2(Point2 p);
[[nodiscard]] std::string format_vec3(Vec3 v);
[[nodiscard]] std::string format_polygon(const Polygon& polygon);
[[nodiscard]] std::string format_polygons(const std::vector<Polygon>& polygons);

}  // namespace roomcad
