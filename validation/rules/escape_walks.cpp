// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/escape_walks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "validation/rules/door_geometry.h"

namespace roomcad::rules {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kOffWall = 0.01;  ///< how far door points and corners stand off the walls

double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }
double cross3(Point2 o, Point2 a, Point2 b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double segment_distance(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return distance(p, {a.x + t * dx, a.y + t * dy});
}

bool cross_properly(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double d1 = cross3(a, b, c), d2 = cross3(a, b, d), d3 = cross3(c, d, a),
               d4 = cross3(c, d, b);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

double segments_distance(Point2 a, Point2 b, Point2 c, Point2 d) {
  if (cross_properly(a, b, c, d)) return 0.0;
  return std::min({segment_distance(a, c, d), segment_distance(b, c, d), segment_distance(c, a, b),
                   segment_distance(d, a, b)});
}

/// Shortest distances from the sources (distance 0) over weighted links. O(E log V).
std::vector<double> dijkstra(const std::vector<std::vector<std::pair<std::size_t, double>>>& links,
                             const std::vector<std::size_t>& sources) {
  std::vector<double> dist(links.size(), kInf);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (const std::size_t s : sources) dist[s] = 0, queue.push({0.0, s});
  while (!queue.empty()) {
    const auto [d, x] = queue.top();
    queue.pop();
    if (d > dist[x]) continue;
    for (const auto& [y, w] : links[x])
      if (d + w < dist[y]) dist[y] = d + w, queue.push({dist[y], y});
  }
  return dist;
}

Point2 hole_end(const Wall& w, double along) {
  const WallFrame<double> f = wall_frame<double>(w);
  const Pt<double> p = f.at(along, 0.0);
  return {p.x, p.y};
}

}  // namespace

std::vector<Point2> EscapeWalks::door_points(const Wall& w, double lo, double hi, int side) {
  const WallFrame<double> f = wall_frame<double>(w);
  const double in = std::min(0.1, (hi - lo) / 4);
  std::vector<Point2> out;
  for (const double u : {lo + in, (lo + hi) / 2, hi - in}) {
    const Pt<double> p = f.at(u, side * (f.half + kOffWall));
    out.push_back({p.x, p.y});
  }
  return out;
}

EscapeWalks::EscapeWalks(const Scene& scene, const Storey& storey)
    : scene_(scene),
      storey_(storey),
      room_points_(storey.rooms.size()),
      convex_(storey.rooms.size(), true) {
  for (std::size_t r = 0; r < storey.rooms.size(); ++r) {
    const std::vector<Point2>& o = storey.rooms[r].outline;
    for (std::size_t i = 0; i < o.size(); ++i) {
      const Point2 a = o[(i + o.size() - 1) % o.size()], v = o[i], b = o[(i + 1) % o.size()];
      if (cross3(a, v, b) >= 0) continue;  // a convex corner
      convex_[r] = false;
      const double la = distance(a, v), lb = distance(v, b);
      if (la == 0 || lb == 0) continue;
      Point2 bis{(a.x - v.x) / la + (b.x - v.x) / lb, (a.y - v.y) / la + (b.y - v.y) / lb};
      const double len = std::hypot(bis.x, bis.y);
      bis = len > 0 ? Point2{-bis.x / len, -bis.y / len}
                    : Point2{(a.y - b.y) / distance(a, b), (b.x - a.x) / distance(a, b)};
      room_points_[r].push_back(points_.size());
      points_.push_back({{v.x + kOffWall * bis.x, v.y + kOffWall * bis.y}, r});
    }
  }
  links_.resize(points_.size());
  for (std::size_t d = 0; d < storey.doors.size(); ++d)
    add_door_points(d, *scene.host(storey.doors[d]));
  link_rooms();
  find_upper_walks();
  find_lower_walks();
}

void EscapeWalks::add_door_points(std::size_t d, std::size_t wall) {
  const Opening& o = scene_.plan().openings[storey_.doors[d]];
  const Wall& w = scene_.plan().walls[wall];
  std::vector<std::size_t> sides[2];
  for (int k = 0; k < 2; ++k) {
    const std::optional<std::size_t> room = storey_.door_rooms[d][k];
    for (const Point2& p : door_points(w, o.offset, o.offset + o.width, k == 1 ? 1 : -1)) {
      sides[k].push_back(points_.size());
      if (room) room_points_[*room].push_back(points_.size());
      points_.push_back({p, room});
      links_.emplace_back();
    }
  }
  for (const std::size_t a : sides[0])
    for (const std::size_t b : sides[1]) {
      const double len = distance(points_[a].p, points_[b].p);  // straight through the hole
      links_[a].push_back({b, len});
      links_[b].push_back({a, len});
    }
}

bool EscapeWalks::is_visible(std::size_t room, Point2 a, Point2 b) const {
  return convex_[room] || is_segment_inside_outline(storey_.rooms[room].outline, a, b);
}

void EscapeWalks::link_rooms() {
  for (std::size_t r = 0; r < room_points_.size(); ++r) {
    const std::vector<std::size_t>& pts = room_points_[r];
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size(); ++j) {
        if (!is_visible(r, points_[pts[i]].p, points_[pts[j]].p)) continue;
        const double len = distance(points_[pts[i]].p, points_[pts[j]].p);
        links_[pts[i]].push_back({pts[j], len});
        links_[pts[j]].push_back({pts[i], len});
      }
  }
}

void EscapeWalks::find_upper_walks() {
  std::vector<std::size_t> exits;
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (!points_[i].room) exits.push_back(i);
  upper_ = dijkstra(links_, exits);
}

void EscapeWalks::find_lower_walks() {
  const Plan& plan = scene_.plan();
  const std::size_t n = storey_.doors.size();
  std::vector<std::pair<Point2, Point2>> holes;
  std::vector<std::vector<std::size_t>>& doors_of = room_doors_;
  doors_of.assign(storey_.rooms.size(), {});
  std::vector<std::size_t> exits;
  for (std::size_t d = 0; d < n; ++d) {
    const Opening& o = plan.openings[storey_.doors[d]];
    const Wall& w = plan.walls[*scene_.host(storey_.doors[d])];
    holes.emplace_back(hole_end(w, o.offset), hole_end(w, o.offset + o.width));
    for (const std::optional<std::size_t>& r : storey_.door_rooms[d]) {
      if (r) doors_of[*r].push_back(d);
      else exits.push_back(d);
    }
  }
  std::vector<std::vector<std::pair<std::size_t, double>>> links(n);
  for (const std::vector<std::size_t>& doors : doors_of)
    for (std::size_t i = 0; i < doors.size(); ++i)
      for (std::size_t j = i + 1; j < doors.size(); ++j) {
        const auto& [a, b] = holes[doors[i]];
        const auto& [c, d] = holes[doors[j]];
        const double len = segments_distance(a, b, c, d);
        links[doors[i]].push_back({doors[j], len});
        links[doors[j]].push_back({doors[i], len});
      }
  lower_ = dijkstra(links, exits);
}

std::vector<Point2> EscapeWalks::samples(std::size_t room, double spacing) const {
  const std::vector<Point2>& o = storey_.rooms[room].outline;
  const Box2 box = room_box(storey_.rooms[room]);
  std::vector<Point2> out;
  for (std::size_t i = 0; i < o.size(); ++i) {  // along the sides, pulled 1 cm inward
    const Point2 a = o[i], b = o[(i + 1) % o.size()];
    const double len = distance(a, b);
    if (len == 0) continue;
    const Point2 in{-(b.y - a.y) / len * kOffWall, (b.x - a.x) / len * kOffWall};
    const int steps = std::max(1, static_cast<int>(std::ceil(len / spacing)));
    for (int k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      const Point2 p{a.x + t * (b.x - a.x) + in.x, a.y + t * (b.y - a.y) + in.y};
      if (is_inside_outline(o, p)) out.push_back(p);
    }
  }
  for (double y = box.min_y + spacing / 2; y < box.max_y; y += spacing)
    for (double x = box.min_x + spacing / 2; x < box.max_x; x += spacing)
      if (is_inside_outline(o, {x, y})) out.push_back({x, y});
  return out;
}

std::optional<WalkBounds> EscapeWalks::longest_walk(std::size_t room, double spacing) const {
  const std::vector<std::size_t>& pts = room_points_[room];
  if (std::none_of(pts.begin(), pts.end(), [&](std::size_t i) { return upper_[i] < kInf; }))
    return std::nullopt;
  const std::vector<std::size_t>& doors = room_doors_[room];
  const Plan& plan = scene_.plan();
  WalkBounds bounds{0.0, 0.0, {}};
  for (const Point2& p : samples(room, spacing)) {
    double up = kInf, low = kInf;
    for (const std::size_t i : pts)
      if (upper_[i] < kInf && is_visible(room, p, points_[i].p))
        up = std::min(up, upper_[i] + distance(p, points_[i].p));
    for (const std::size_t d : doors) {
      const Opening& o = plan.openings[storey_.doors[d]];
      const Wall& w = plan.walls[*scene_.host(storey_.doors[d])];
      low = std::min(
          low,
          segment_distance(p, hole_end(w, o.offset), hole_end(w, o.offset + o.width)) + lower_[d]);
    }
    if (up < kInf && up > bounds.upper) bounds.upper = up, bounds.farthest = p;
    if (low < kInf) bounds.lower = std::max(bounds.lower, low);
  }
  bounds.upper += spacing;
  return bounds;
}

double EscapeWalks::walk_to(std::size_t room, const std::vector<Point2>& exits, double beyond,
                            double spacing) const {
  double longest = 0;
  for (const Point2& p : samples(room, spacing)) {
    double up = kInf;
    for (const Point2& q : exits)
      if (is_visible(room, p, q)) up = std::min(up, distance(p, q) + beyond);
    longest = std::max(longest, up);
  }
  return longest + spacing;
}

}  // namespace roomcad::rules
