// Strict parsing of the values typed on the command line and given to set_field: a whole
// string or nothing, never a prefix ("1.5m" is not 1.5), never NaN or infinity.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "modeling/plan.h"

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

/// The enums of the format, by the names the format writes (to_string in modeling/plan.h).
[[nodiscard]] std::optional<OpeningType> parse_opening_type(std::string_view text);
[[nodiscard]] std::optional<Hinge> parse_hinge(std::string_view text);
[[nodiscard]] std::optional<Swing> parse_swing(std::string_view text);
[[nodiscard]] std::optional<LightType> parse_light_type(std::string_view text);
[[nodiscard]] std::optional<Projection> parse_projection(std::string_view text);

}  // namespace roomcad
