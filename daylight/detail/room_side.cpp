// SPDX-License-Identifier: GPL-3.0-or-later
#include "daylight/detail/room_side.h"

#include <algorithm>

namespace roomcad::daylight_detail {
namespace {

/// Even-odd point in polygon, doubles: the probe is a centimetre from any wall face.
bool inside(const std::vector<Point2>& polygon, Point2 p) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    if ((polygon[i].y > p.y) != (polygon[j].y > p.y) &&
        p.x < (polygon[j].x - polygon[i].x) * (p.y - polygon[i].y) / (polygon[j].y - polygon[i].y) +
                  polygon[i].x)
      in = !in;
  return in;
}

}  // namespace

double room_side(const std::vector<Point2>& outline, Point2 at, Point2 u, double half_thickness) {
  if (outline.size() < 3) return 1.0;
  const double probe = half_thickness + std::min(0.01, half_thickness);
  return inside(outline, {at.x - u.y * probe, at.y + u.x * probe}) ? 1.0 : -1.0;
}

}  // namespace roomcad::daylight_detail
