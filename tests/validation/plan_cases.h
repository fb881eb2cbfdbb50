// SPDX-License-Identifier: GPL-3.0-or-later
// Plans for validation tests: small builders, and a frame that moves a case far from the
// origin and rotates it.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "testing/plan_builders.h"
#include "validation/report.h"
#include "validation/validate.h"

namespace roomcad::testing {

using samples::make_opening;
using samples::make_wall;

/// A plan on a large site centred on the origin (so that rotated cases stay inside).
inline Plan plan_with(std::vector<Wall> walls, std::vector<Opening> openings = {}) {
  Plan p;
  p.site.origin = {-64, -64};
  p.site.cells = {128, 128};
  p.walls = std::move(walls);
  p.openings = std::move(openings);
  return p;
}

using Codes = std::vector<Code>;
using Ids = std::vector<std::string>;

/// @return the codes of the report's errors (warnings left out), in order.
inline Codes error_codes(const Report& r) {
  Codes out;
  for (const Diagnostic& d : r.items)
    if (d.severity == Severity::error) out.push_back(d.code);
  return out;
}

inline ValidateOptions no_rooms() {
  ValidateOptions o;
  o.room_warnings = false;
  return o;
}

/// A rigid motion applied to a case built in its own (local) frame: rotate by `degrees`
/// about the local origin, then translate by `offset`.
///
/// Why the verdicts stay well defined: every world coordinate is computed from its local
/// one and rounded once, so each point moves by at most a few ulps of its magnitude
/// (2^20 m -> ulp 2^-32 m, about 2.3e-10 m). The cases put a gap or an overlap of 1e-6 m
/// between shapes, 4000 times that error, so a gap stays a gap and an overlap an overlap
/// after the motion; and points shared in the local frame (a wall end used by two walls)
/// map to bit-identical world points, so joins stay joins. What cannot survive is exact
/// touching: it is tested only in frames that keep the numbers exact (axis-aligned, and
/// translations by 2^20 of dyadic coordinates).
struct Frame {
  double degrees = 0;
  Point2 offset{0, 0};

  [[nodiscard]] Point2 map(Point2 p) const {
    if (degrees == 0) return {p.x + offset.x, p.y + offset.y};
    const double a = degrees * M_PI / 180;
    return {offset.x + (p.x * std::cos(a) - p.y * std::sin(a)),
            offset.y + (p.x * std::sin(a) + p.y * std::cos(a))};
  }

  /// Moves the walls and the site's origin. Rotated frames get a site large enough to hold
  /// the whole case (out_of_bounds is tested separately).
  [[nodiscard]] Plan apply(Plan p) const {
    for (Wall& w : p.walls) {
      w.from = map(w.from);
      w.to = map(w.to);
    }
    if (degrees == 0) {
      p.site.origin = map(p.site.origin);
    } else {
      const std::int64_t span = std::max(p.site.cells[0], p.site.cells[1]) * 2;
      p.site.origin = {offset.x - span * p.site.cell_size / 2,
                       offset.y - span * p.site.cell_size / 2};
      p.site.cells = {span, span};
    }
    return p;
  }
};

/// The frames every geometric case is checked in: as written, moved 2^20 m, and rotated by
/// 30, 45 and 71.3 degrees (also moved 2^20 m).
inline std::vector<Frame> all_frames() {
  const Point2 far{1048576.0, -1048576.0};
  return {Frame{0, {0, 0}}, Frame{0, far},    Frame{30, far},
          Frame{45, far},   Frame{71.3, far}, Frame{30, {0, 0}}};
}

}  // namespace roomcad::testing
