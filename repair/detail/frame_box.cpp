// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/detail/frame_box.h"

#include "geometry/segment_predicates.h"
#include "plan/plan_levels.h"

namespace roomcad::detail {

bool on_one_line(const Wall& a, const Wall& b) {
  return are_parallel(a.from, a.to, a.from, b.from) && are_parallel(a.from, a.to, a.from, b.to);
}

double wall_length(const Wall& w) { return std::hypot(w.to.x - w.from.x, w.to.y - w.from.y); }

LineFrame line_frame(const Wall& w) {
  const double length = wall_length(w);
  return {w.from, {(w.to.x - w.from.x) / length, (w.to.y - w.from.y) / length}};
}

bool is_plain_wall(const Wall& w) {
  const bool flat = !w.height_at_end || *w.height_at_end == w.height;
  return flat && !w.arc_extent && std::isfinite(w.from.x) && std::isfinite(w.from.y) &&
         std::isfinite(w.to.x) && std::isfinite(w.to.y) && w.from != w.to && w.thickness > 0 &&
         w.height > 0 && std::isfinite(w.thickness) && std::isfinite(w.height) &&
         std::isfinite(w.base);
}

FrameBox frame_box(const Plan& plan, const LineFrame& frame, const Wall& w) {
  const double s0 = frame.s(w.from), s1 = frame.s(w.to);
  const double n0 = frame.n(w.from), n1 = frame.n(w.to);
  const double half = w.thickness / 2;
  const double base = base_z(plan, w);
  return {{std::min(s0, s1), std::max(s0, s1)},
          {std::min(n0, n1) - half, std::max(n0, n1) + half},
          {base, base + w.height}};
}

}  // namespace roomcad::detail
