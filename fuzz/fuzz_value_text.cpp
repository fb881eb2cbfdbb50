// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the strict value parsers of the command line and set_field
// (plan/value_text.h) and colours (plan/plan.h) on arbitrary text. Any crash, sanitizer
// report or hang is a bug, and so is a number parsed as not finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "plan/plan.h"
#include "plan/value_text.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (const auto number = roomcad::parse_number(text); number && !std::isfinite(*number))
    __builtin_trap();
  (void)roomcad::parse_integer(text);
  (void)roomcad::parse_point2(text);
  (void)roomcad::parse_vec3(text);
  (void)roomcad::parse_cells(text);
  (void)roomcad::parse_polygon(text);
  (void)roomcad::parse_polygons(text);
  (void)roomcad::parse_enum<roomcad::OpeningType>(text);
  (void)roomcad::parse_enum<roomcad::Hinge>(text);
  (void)roomcad::parse_enum<roomcad::Swing>(text);
  (void)roomcad::parse_enum<roomcad::LightType>(text);
  (void)roomcad::parse_enum<roomcad::Projection>(text);
  if (const auto colour = roomcad::parse_color(text))
    if (roomcad::parse_color(roomcad::to_string(*colour)) != colour) __builtin_trap();
  return 0;
}
