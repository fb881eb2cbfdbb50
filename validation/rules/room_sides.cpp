// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/room_sides.h"

#include <algorithm>
#include <cmath>

#include "validation/rules/fix_search.h"

namespace roomcad::rules {
namespace {

struct Frame {
  Point2 from;
  Point2 u;
  double length;
  double along(Point2 p) const { return (p.x - from.x) * u.x + (p.y - from.y) * u.y; }
  double across(Point2 p) const { return -(p.x - from.x) * u.y + (p.y - from.y) * u.x; }
};

Frame frame_of(const Wall& w) {
  const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
  return {w.from, {(w.to.x - w.from.x) / length, (w.to.y - w.from.y) / length}, length};
}

}  // namespace

std::vector<RoomSide> room_sides(const Scene& scene, const Room& room) {
  const Plan& plan = scene.plan();
  std::vector<RoomSide> out;
  const std::size_t n = room.outline.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2 p = room.outline[k], q = room.outline[(k + 1) % n];
    const double tol =
        1e-6 + 1e-9 * std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y)});
    for (const std::string& id : room.walls) {
      const std::optional<std::size_t> index = scene.wall_named(id);
      if (!index) continue;
      const Wall& w = plan.walls[*index];
      const Frame f = frame_of(w);
      const double half = w.thickness / 2;
      for (const int side : {1, -1}) {
        if (std::fabs(f.across(p) - side * half) > tol ||
            std::fabs(f.across(q) - side * half) > tol)
          continue;
        const double lo = std::min(f.along(p), f.along(q)), hi = std::max(f.along(p), f.along(q));
        if (hi - lo > tol && hi > -tol && lo < f.length + tol)
          out.push_back({*index, side, lo, hi});
      }
    }
  }
  return out;
}

Point2 beyond_side(const Plan& plan, const RoomSide& s, double along, double across) {
  const Wall& w = plan.walls[s.wall];
  const Frame f = frame_of(w);
  // The room lies on side s.side of the wall; beyond its far face is side -s.side.
  const double v = -s.side * (w.thickness / 2 + across);
  return {w.from.x + along * f.u.x - v * f.u.y, w.from.y + along * f.u.y + v * f.u.x};
}

std::vector<double> door_offsets(const Scene& scene, const RoomSide& s, double width) {
  const Plan& plan = scene.plan();
  const double length = frame_of(plan.walls[s.wall]).length;
  const double lo = std::max(s.lo, 0.0) + 0.05, hi = std::min(s.hi, length) - 0.05 - width;
  if (hi < lo) return {};
  std::vector<double> out{centimetres_down((lo + hi) / 2)};
  for (long long k = static_cast<long long>(std::ceil(lo * 20)); static_cast<double>(k) / 20 <= hi;
       ++k)
    out.push_back(static_cast<double>(k * 5) / 100);
  std::stable_sort(out.begin() + 1, out.end(), [&](double a, double b) {
    return std::fabs(a - out[0]) < std::fabs(b - out[0]);
  });
  const auto is_taken = [&](double offset) {
    for (const std::size_t i : scene.openings_of(s.wall)) {
      const Opening& o = plan.openings[i];
      if (offset < o.offset + o.width && o.offset < offset + width) return true;
    }
    return false;
  };
  std::erase_if(out, [&](double o) { return o < lo - 1e-9 || o > hi + 1e-9 || is_taken(o); });
  return out;
}

FixEdit add_door_edit(const std::string& id, const std::string& wall, double offset, double width) {
  FixEdit e;
  e.op = FixEdit::Op::add;
  e.id = id;
  e.fields = {{"type", "door"},
              {"wall", wall},
              {"offset", number_text(offset)},
              {"width", number_text(width)}};
  return e;
}

}  // namespace roomcad::rules
