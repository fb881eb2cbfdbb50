// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/fast_path/tees.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace roomcad::detail {
namespace {

double w_on(const WallFrame& f, Point2 p) {
  return (p.x - f.from.x) * f.normal.x + (p.y - f.from.y) * f.normal.y;
}

// Where the line p + t d crosses the through-wall's side line on `side`.
Point2 cross_side(const WallFrame& t, int side, Point2 p, Point2 d) {
  const Point2 q{t.from.x + t.normal.x * t.half * side, t.from.y + t.normal.y * t.half * side};
  const double s = cross({q.x - p.x, q.y - p.y}, t.dir) / cross(d, t.dir);
  return {p.x + d.x * s, p.y + d.y * s};
}

// The u range where the through-wall's side faces exist on both sides (clear of its ends).
std::pair<double, double> clear_range(const WallFrame& t) {
  const double lo = std::max(u_of(t, t.footprint[0]), u_of(t, t.footprint[3]));
  const double hi = std::min(u_of(t, t.footprint[1]), u_of(t, t.footprint[2]));
  return {std::max(lo, 0.0), std::min(hi, t.length)};
}

std::optional<Tee> make_tee(const std::vector<WallFrame>& frames, std::size_t stem, WallEnd end,
                            std::size_t through) {
  const WallFrame& s = frames[stem];
  const WallFrame& t = frames[through];
  // A stem as high as the through-wall or lower (a garden wall), standing on the same base.
  if (s.base != t.base || s.top > t.top || s.capless[std::size_t(end)]) return std::nullopt;
  const Point2 e = end == WallEnd::from ? s.from : s.to;
  const Point2 out = end == WallEnd::from ? s.dir : Point2{-s.dir.x, -s.dir.y};
  const double u = u_of(t, e), w = w_on(t, e), along = out.x * t.normal.x + out.y * t.normal.y;
  if (std::abs(w) > t.half / 2 || std::abs(cross(out, t.dir)) < 0.5) return std::nullopt;
  const int side = along > 0 ? 1 : -1;
  const Point2 n{-out.y * s.half, out.x * s.half};  // left of the outward direction
  const Point2 left = cross_side(t, side, {e.x + n.x, e.y + n.y}, out);
  const Point2 right = cross_side(t, side, {e.x - n.x, e.y - n.y}, out);
  Tee tee{stem, end, through, {}, {right, left}};
  const double ul = u_of(t, left), ur = u_of(t, right);
  tee.attachment = ul < ur ? Attachment{ul, ur, side, left, right, s.top}
                           : Attachment{ur, ul, side, right, left, s.top};
  const auto [lo, hi] = clear_range(t);
  if (!(tee.attachment.u0 > lo && tee.attachment.u1 < hi) || !(u > 0.0 && u < t.length))
    return std::nullopt;
  // What the clip takes off the stem must lie inside the through-wall: its square end's
  // corners too (a stem thicker than the wall, or meeting it askew, reaches past its far face).
  for (const Point2 corner : {Point2{e.x + n.x, e.y + n.y}, Point2{e.x - n.x, e.y - n.y}}) {
    const double cu = u_of(t, corner);
    if (std::abs(w_on(t, corner)) > t.half || !(cu > lo && cu < hi)) return std::nullopt;
  }
  for (const Hole& h : t.holes)
    if (!(h.u1 < tee.attachment.u0 || h.u0 > tee.attachment.u1)) return std::nullopt;
  return tee;
}

bool overlaps(const Attachment& a, const Attachment& b) {
  return a.side == b.side && !(a.u1 < b.u0 || b.u1 < a.u0);
}

}  // namespace

std::vector<Tee> find_tees(const std::vector<WallFrame>& frames, const Joins& joins) {
  std::vector<std::size_t> unite_count(2 * frames.size(), 0);  // per wall end
  std::vector<Tee> candidates;
  for (const Join& j : joins.pairs) {
    if (j.kind != JoinKind::unite) continue;
    for (const auto& [stem, through] : {std::pair{j.a, j.b}, std::pair{j.b, j.a}}) {
      const WallFrame& s = frames[stem];
      for (const WallEnd end : {WallEnd::from, WallEnd::to}) {
        const Point2 e = end == WallEnd::from ? s.from : s.to;
        if (std::hypot(e.x - j.point.x, e.y - j.point.y) > s.half) continue;
        ++unite_count[2 * stem + std::size_t(end)];
        if (auto tee = make_tee(frames, stem, end, through)) candidates.push_back(*tee);
      }
    }
  }
  std::vector<Tee> tees;
  for (const Tee& c : candidates) {
    if (unite_count[2 * c.stem + std::size_t(c.end)] != 1) continue;  // another wall meets there
    const bool clash = std::any_of(tees.begin(), tees.end(), [&](const Tee& t) {
      return t.through == c.through && overlaps(t.attachment, c.attachment);
    });
    if (!clash) tees.push_back(c);
  }
  return tees;
}

void attach_tees(const std::vector<Tee>& tees, std::vector<WallFrame>& frames) {
  for (const Tee& t : tees) {
    WallFrame& s = frames[t.stem];
    // Footprint order {from-right, to-right, to-left, from-left}; at the to end, looking
    // outward swaps the wall's left and right.
    if (t.end == WallEnd::from) s.footprint[0] = t.clip[0], s.footprint[3] = t.clip[1];
    else s.footprint[1] = t.clip[1], s.footprint[2] = t.clip[0];
    s.capless[std::size_t(t.end)] = true;
    frames[t.through].attachments.push_back(t.attachment);
  }
}

}  // namespace roomcad::detail
