// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/arc_chords.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/error.h"

namespace roomcad {

double chord_tolerance_of(const Site& site) {
  return site.chord_tolerance.value_or(kDefaultChordTolerance);
}

std::size_t chord_count(double span, double extent_deg, double tolerance) {
  const double theta = std::abs(extent_deg) * std::numbers::pi / 180.0;
  const double radius = span / (2.0 * std::sin(theta / 2.0));
  for (std::size_t n = 1; n <= kMaxChords; ++n)
    if (radius * (1.0 - std::cos(theta / (2.0 * double(n)))) <= tolerance) return n;
  return kMaxChords + 1;
}

std::vector<Point2> chord_polyline(const Wall& wall, double chord_tolerance) {
  if (!wall.arc_extent) return {wall.from, wall.to};
  const double extent = *wall.arc_extent;
  const double dx = wall.to.x - wall.from.x, dy = wall.to.y - wall.from.y,
               span = std::hypot(dx, dy);
  if (!(std::abs(extent) > 0.0 && std::abs(extent) < 360.0) || !(span > 0.0) ||
      !std::isfinite(span))
    throw PreconditionError(
        fmt::format("build_model: wall '{}' cannot be built: arc_extent {} over a chord of {} m "
                    "(0 < |arc_extent| < 360 and a positive length)",
                    wall.id, extent, span),
        Code::not_buildable);
  const std::size_t n = chord_count(span, extent, chord_tolerance);
  if (n > kMaxChords)
    throw PreconditionError(
        fmt::format("build_model: wall '{}' needs more than {} chords for its arc_extent {} "
                    "within the chord tolerance {} m",
                    wall.id, kMaxChords, extent, chord_tolerance),
        Code::too_large);
  // The centre is on the bisector of from -> to, (span / 2) / tan(theta / 2) to its left
  // (to its right when theta is negative or past 180 degrees: tan changes sign).
  const double theta = extent * std::numbers::pi / 180.0,
               along = span / 2.0 / std::tan(theta / 2.0);
  const Point2 centre{wall.from.x + dx / 2.0 - dy / span * along,
                      wall.from.y + dy / 2.0 + dx / span * along};
  const double rx = wall.from.x - centre.x, ry = wall.from.y - centre.y;
  std::vector<Point2> points{wall.from};
  for (std::size_t k = 1; k < n; ++k) {
    const double a = theta * double(k) / double(n), c = std::cos(a), s = std::sin(a);
    points.push_back({centre.x + c * rx - s * ry, centre.y + s * rx + c * ry});
  }
  points.push_back(wall.to);
  return points;
}

}  // namespace roomcad
