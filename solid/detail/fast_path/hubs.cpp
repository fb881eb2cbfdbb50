// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/fast_path/hubs.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>

namespace roomcad::detail {
namespace {

using Arm = std::pair<std::size_t, WallEnd>;

const Point2& end_point(const WallFrame& f, WallEnd end) {
  return end == WallEnd::from ? f.from : f.to;
}

double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }

// A point on the arm's left (side = +1) or right (-1) side line, seen going outward.
Point2 side_origin(const WallFrame& f, WallEnd end, int side) {
  const Point2 e = outward(f, end), p = end_point(f, end);
  return {p.x - e.y * f.half * side, p.y + e.x * f.half * side};
}

// The crossing of arm a's left side line with arm b's right side line (b follows a
// counter-clockwise, 90 to 180 degrees on). For collinear arms, their common side point.
Point2 corner(const WallFrame& a, WallEnd ea, const WallFrame& b, WallEnd eb) {
  const Point2 da = outward(a, ea), db = outward(b, eb);
  const Point2 pa = side_origin(a, ea, 1), pb = side_origin(b, eb, -1);
  const double denom = cross(da, db);
  if (denom == 0.0) return pa;
  const double t = cross({pb.x - pa.x, pb.y - pa.y}, db) / denom;
  return {pa.x + da.x * t, pa.y + da.y * t};
}

// Arms 90 to 180 degrees apart tile the union only where each corner lies on both arms' side
// lines ahead of the node: arms nearly collinear of unequal thickness cross their side lines
// behind it (the thinner arm's side reaches the thicker's end face, not its side), which would
// put hub corners outside the union (170 degrees, 0.2 m on to 0.1 m: 0.28 m behind the node).
// The corners are doubles, so "ahead" allows rounding: -1e-12 of the thicknesses.
bool is_valid_hub(const std::vector<WallFrame>& frames, const Hub& hub) {
  const std::vector<Arm>& arms = hub.arms;
  const WallFrame& first = frames[arms.front().first];
  const Point2 node = end_point(first, arms.front().second);
  for (std::size_t k = 0; k < arms.size(); ++k) {
    const WallFrame& a = frames[arms[k].first];
    const WallFrame& b = frames[arms[(k + 1) % arms.size()].first];
    if (a.base != first.base || a.top != first.top) return false;
    const Point2 da = outward(a, arms[k].second),
                 db = outward(b, arms[(k + 1) % arms.size()].second);
    const double c = cross(da, db), d = dot(da, db);
    if (d > 0.0 || c < 0.0) return false;            // closer than 90 or beyond 180 degrees
    if (c == 0.0 && a.half != b.half) return false;  // collinear arms of unequal thickness
    const Point2 to_corner{hub.corners[k].x - node.x, hub.corners[k].y - node.y};
    const double behind = -1e-12 * (a.half + b.half);
    if (dot(to_corner, da) < behind || dot(to_corner, db) < behind) return false;
  }
  return true;
}

bool are_all_joined(const Joins& joins, const std::vector<Arm>& arms) {
  for (std::size_t i = 0; i < arms.size(); ++i)
    for (std::size_t j = i + 1; j < arms.size(); ++j)
      if (!joins.are_joined(arms[i].first, arms[j].first)) return false;
  return true;
}

Hub make_hub(const std::vector<WallFrame>& frames, std::vector<Arm> arms) {
  std::sort(arms.begin(), arms.end(), [&](const Arm& x, const Arm& y) {
    const Point2 a = outward(frames[x.first], x.second), b = outward(frames[y.first], y.second);
    return std::atan2(a.y, a.x) < std::atan2(b.y, b.x);
  });
  Hub hub{arms, {}};
  for (std::size_t k = 0; k < arms.size(); ++k) {
    const Arm& a = arms[k];
    const Arm& b = arms[(k + 1) % arms.size()];
    hub.corners.push_back(corner(frames[a.first], a.second, frames[b.first], b.second));
  }
  return hub;
}

}  // namespace

std::vector<Hub> find_hubs(const std::vector<WallFrame>& frames, const Joins& joins) {
  std::map<std::pair<std::uint64_t, std::uint64_t>, std::vector<Arm>> nodes;
  for (std::size_t i = 0; i < frames.size(); ++i)
    for (const WallEnd end : {WallEnd::from, WallEnd::to}) {
      const Point2& p = end_point(frames[i], end);
      nodes[{std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0)}]
          .emplace_back(i, end);
    }
  std::vector<Hub> hubs;
  for (auto& [point, arms] : nodes) {
    if (arms.size() < 3 || !are_all_joined(joins, arms)) continue;
    Hub hub = make_hub(frames, std::move(arms));
    // Arms a denormal off collinear put a corner at infinity: such a node is the general path's.
    const bool finite = std::all_of(hub.corners.begin(), hub.corners.end(), [](Point2 c) {
      return std::isfinite(c.x) && std::isfinite(c.y);
    });
    if (finite && is_valid_hub(frames, hub)) hubs.push_back(std::move(hub));
  }
  auto first_wall = [](const Hub& h) {
    return std::min_element(h.arms.begin(), h.arms.end())->first;
  };
  std::sort(hubs.begin(), hubs.end(),
            [&](const Hub& a, const Hub& b) { return first_wall(a) < first_wall(b); });
  return hubs;
}

void attach_hub(const Hub& hub, std::vector<WallFrame>& frames) {
  const std::size_t k = hub.arms.size();
  for (std::size_t i = 0; i < k; ++i) {
    const auto [wall, end] = hub.arms[i];
    const Point2 left = hub.corners[i], right = hub.corners[(i + k - 1) % k];  // seen outward
    WallFrame& f = frames[wall];
    // Footprint order {from-right, to-right, to-left, from-left} in the wall's own frame;
    // at the to end, looking outward swaps the wall's left and right.
    if (end == WallEnd::from) f.footprint[0] = right, f.footprint[3] = left;
    else f.footprint[1] = left, f.footprint[2] = right;
    f.capless[static_cast<std::size_t>(end)] = true;
  }
}

FaceSoup build_hub(const Hub& hub, const std::vector<WallFrame>& frames) {
  const WallFrame& owner = frames[std::min_element(hub.arms.begin(), hub.arms.end())->first];
  const int object = static_cast<int>(owner.wall);
  SoupFace top{{}, FaceKind::wall_top, object, owner.color, {}, {}};
  SoupFace bottom{{}, FaceKind::wall_bottom, object, owner.color, {}, {}};
  for (const Point2& c : hub.corners) top.points.emplace_back(c.x, c.y, owner.top);
  for (auto c = hub.corners.rbegin(); c != hub.corners.rend(); ++c)
    bottom.points.emplace_back(c->x, c->y, owner.base);
  return {top, bottom};
}

}  // namespace roomcad::detail
