// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/signed_area.h"

namespace roomcad {

double signed_area(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

}  // namespace roomcad
