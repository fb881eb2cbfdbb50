// SPDX-License-Identifier: GPL-3.0-or-later
// Small builders of plan objects for tests and benchmarks: one wall, one opening.
#pragma once

#include <string>
#include <utility>

#include "plan/plan.h"

namespace roomcad::samples {

/// A wall of `thickness` and `height` (the defaults of most validation cases).
inline Wall make_wall(std::string id, Point2 from, Point2 to, double thickness = 0.25,
                      double height = 2.5) {
  Wall w;
  w.id = std::move(id);
  w.from = from;
  w.to = to;
  w.thickness = thickness;
  w.height = height;
  return w;
}

/// An opening of every size given.
inline Opening make_opening(std::string id, OpeningType type, std::string wall, double offset,
                            double width, double height, double sill) {
  Opening o;
  o.id = std::move(id);
  o.type = type;
  o.wall = std::move(wall);
  o.offset = offset;
  o.width = width;
  o.height = height;
  o.sill = sill;
  return o;
}

}  // namespace roomcad::samples
