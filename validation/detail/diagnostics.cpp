// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/detail/diagnostics.h"

#include <cmath>

#include <fmt/format.h>

namespace roomcad::detail {

std::string metres(double value) {
  if (value != 0.0 && std::fabs(value) < 0.005) return fmt::format("{:.3g} m", value);
  return fmt::format("{:.2f} m", value);
}

std::string exact_metres(double value) {
  const double millimetres = std::round(value * 1000.0) / 1000.0;
  if (millimetres == value) return fmt::format("{} m", value == 0.0 ? 0.0 : value);
  return fmt::format("{:.3f} m (exactly {} m)", millimetres, value);
}

std::string metres_at_least(double value) {
  if (value < 0.005) return metres(value);
  return fmt::format("{:.2f} m", std::ceil(value * 100 - 1e-7) / 100);
}

std::string metres_at_most(double value) {
  if (value < 0.005) return metres(value);
  return fmt::format("{:.2f} m", std::floor(value * 100 + 1e-7) / 100);
}

std::string point_text(Point2 p) { return fmt::format("({:.2f}, {:.2f})", p.x, p.y); }

std::string direction_text(Point2 unit) {
  static const char* const winds[8] = {"east", "north-east", "north", "north-west",
                                       "west", "south-west", "south", "south-east"};
  const double turns = std::atan2(unit.y, unit.x) / (2 * M_PI);  // in (-0.5, 0.5]
  const int sector = static_cast<int>(std::lround(turns * 8 + 8)) % 8;
  return winds[sector];
}

Where box_where(double min_x, double min_y, double max_x, double max_y) {
  return Where{{min_x, min_y}, Point2{max_x, max_y}};
}

Diagnostic make_diagnostic(Severity severity, Code code, std::vector<std::string> objects,
                           std::string message, std::string fix, std::optional<Where> where) {
  Diagnostic d;
  d.severity = severity;
  d.code = code;
  d.objects = std::move(objects);
  d.message = std::move(message);
  d.fix = std::move(fix);
  d.where = std::move(where);
  return d;
}

std::string name_of(const Wall& w) { return fmt::format("wall '{}'", w.id); }
std::string name_of(const Opening& o) { return fmt::format("{} '{}'", to_string(o.type), o.id); }

}  // namespace roomcad::detail
