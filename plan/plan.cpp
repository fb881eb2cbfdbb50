// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan.h"

#include <cstdio>

namespace roomcad {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::optional<Color> parse_color(std::string_view text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  std::uint8_t channel[3];
  for (int i = 0; i < 3; ++i) {
    const int hi = hex_digit(text[1 + 2 * i]);
    const int lo = hex_digit(text[2 + 2 * i]);
    if (hi < 0 || lo < 0) return std::nullopt;
    channel[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  return Color{channel[0], channel[1], channel[2]};
}

std::string to_string(Color c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

OpeningDefaults opening_defaults(OpeningType type) {
  // The spec's example door and window; a window's sill defaults to 0.9 m, a door's to 0.
  return type == OpeningType::door ? OpeningDefaults{0.9, 2.1, 0.0}
                                   : OpeningDefaults{1.4, 1.3, 0.9};
}

const Wall* find_wall(const Plan& plan, std::string_view id) {
  for (const Wall& w : plan.walls)
    if (w.id == id) return &w;
  return nullptr;
}

Light default_light() {
  Light sun;
  sun.id = "sun";
  return sun;
}

std::string_view to_string(OpeningType t) { return t == OpeningType::door ? "door" : "window"; }
std::string_view to_string(Hinge h) { return h == Hinge::left ? "left" : "right"; }
std::string_view to_string(Swing s) { return s == Swing::in ? "in" : "out"; }
std::string_view to_string(LightType) { return "directional"; }
std::string_view to_string(Projection p) {
  return p == Projection::perspective ? "perspective" : "orthographic";
}

}  // namespace roomcad
