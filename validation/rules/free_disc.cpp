// SPDX-License-Identifier: GPL-3.0-or-later
// Free circles in rooms (see free_disc.h): candidates in doubles, verdicts exact.
#include "validation/rules/free_disc.h"

#include <algorithm>
#include <cmath>

#include "validation/detail/shapes.h"
#include "validation/rules/door_geometry.h"

namespace roomcad::rules {
namespace {

constexpr std::size_t kVerified = 16;  ///< touching candidates rebuilt exactly before giving up
constexpr double kSlack = 1e-6;        ///< metres: candidates this much clear verify in intervals

/// A line of centres at rho from a wall: along its left face (0), right face (1), beyond its
/// from end (2) or its to end (3).
struct LineRef {
  std::size_t wall;
  int kind;
};

/// The line a . p = b with a unit normal a.
template <class NT>
std::pair<Pt<NT>, NT> line_of(const Wall& w, LineRef l, const NT& rho) {
  const WallFrame<NT> f = wall_frame<NT>(w);
  const Pt<NT> d = exact::to_pt<NT>(w.to) - exact::to_pt<NT>(w.from);
  NT c(0);
  Pt<NT> a = f.n;
  switch (l.kind) {
    case 0: c = f.half + rho; break;
    case 1: c = -(f.half + rho); break;
    case 2: a = f.u, c = -rho; break;
    default: a = f.u, c = exact::root(exact::dot(d, d)) + rho; break;
  }
  return {a, exact::dot(f.origin, a) + c};
}

/// @return the crossing of two lines, or nullopt if they are parallel.
template <class NT>
std::optional<Pt<NT>> crossing(const std::pair<Pt<NT>, NT>& l1, const std::pair<Pt<NT>, NT>& l2) {
  const NT det = exact::cross(l1.first, l2.first);
  if (det == NT(0)) return std::nullopt;
  return Pt<NT>{(l1.second * l2.first.y - l2.second * l1.first.y) / det,
                (l1.first.x * l2.second - l2.first.x * l1.second) / det};
}

double distance_to_quad(Point2 p, const std::array<Point2, 4>& q) {
  bool inside = true;
  double best = INFINITY;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point2 a = q[i], b = q[(i + 1) % 4];
    const double ex = b.x - a.x, ey = b.y - a.y;
    if (ex * (p.y - a.y) - ey * (p.x - a.x) < 0) inside = false;
    const double len2 = ex * ex + ey * ey;
    const double t =
        len2 > 0 ? std::clamp(((p.x - a.x) * ex + (p.y - a.y) * ey) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(p.x - a.x - t * ex, p.y - a.y - t * ey));
  }
  return inside ? 0.0 : best;
}

struct DiscCentre {
  Point2 p;
  double clearance;
  std::optional<std::pair<LineRef, LineRef>> lines;  ///< for an exact rebuild
};

/// Candidates where circles of radius rho about wall corners meet the lines, or each other.
void add_arc_candidates(const StoreyWalls& sw, const std::vector<std::size_t>& walls,
                        const std::vector<std::pair<Point2, double>>& lines, double rho,
                        std::vector<Point2>& out) {
  std::vector<Point2> corners;
  for (const std::size_t w : walls)
    for (const Point2& c : sw.quad(w)) corners.push_back(c);
  for (const Point2& c : corners) {
    for (const auto& [a, b] : lines) {  // circle about c meets a . p = b
      const double s = a.x * c.x + a.y * c.y - b;
      if (std::fabs(s) > rho) continue;
      const double t = std::sqrt(rho * rho - s * s);
      const Point2 foot{c.x - s * a.x, c.y - s * a.y};
      out.push_back({foot.x - t * a.y, foot.y + t * a.x});
      out.push_back({foot.x + t * a.y, foot.y - t * a.x});
    }
    for (const Point2& e : corners) {
      const double dx = e.x - c.x, dy = e.y - c.y, d2 = dx * dx + dy * dy;
      if (d2 == 0 || d2 > 4 * rho * rho) continue;
      const double h = std::sqrt(rho * rho / d2 - 0.25);
      out.push_back({c.x + dx / 2 - h * dy, c.y + dy / 2 + h * dx});
    }
  }
}

std::vector<DiscCentre> candidates(const StoreyWalls& sw, const std::vector<std::size_t>& walls,
                                   const RoomLocator& locator, std::size_t room, double rho,
                                   double tol) {
  const Plan& plan = sw.scene().plan();
  std::vector<LineRef> refs;
  std::vector<std::pair<Point2, double>> lines;
  for (const std::size_t w : walls)
    for (int kind = 0; kind < 4; ++kind) {
      refs.push_back({w, kind});
      const auto [a, b] = line_of<double>(plan.walls[w], refs.back(), rho);
      lines.push_back({{a.x, a.y}, b});
    }
  std::vector<DiscCentre> out;
  const auto consider = [&](Point2 p, std::optional<std::pair<LineRef, LineRef>> from) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || locator.locate(p) != room) return;
    const double c = sw.clearance(p, walls);
    if (c >= rho - tol) out.push_back({p, c, from});
  };
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (std::size_t j = i + 1; j < lines.size(); ++j) {
      const auto p =
          crossing(std::pair{Pt<double>{lines[i].first.x, lines[i].first.y}, lines[i].second},
                   std::pair{Pt<double>{lines[j].first.x, lines[j].first.y}, lines[j].second});
      if (p) consider({p->x, p->y}, std::pair{refs[i], refs[j]});
    }
  std::vector<Point2> arcs;
  add_arc_candidates(sw, walls, lines, rho, arcs);
  for (const Point2& p : arcs) consider(p, std::nullopt);
  std::sort(out.begin(), out.end(),
            [](const DiscCentre& a, const DiscCentre& b) { return a.clearance > b.clearance; });
  return out;
}

bool is_clear(const Scene& scene, const std::vector<std::size_t>& walls, Point2 c,
              double diameter) {
  return decide_written([&](auto tag) {
    using NT = decltype(tag);
    const Pt<NT> p{computed<NT>(c.x), computed<NT>(c.y)};
    const NT r = NT(diameter) / NT(2);
    for (const std::size_t w : walls)
      if (is_nearer_than(p, wall_polygon<NT>(scene.plan(), scene.joins(), w), r * r)) return false;
    return true;
  });
}

bool is_clear_rebuilt(const Scene& scene, const std::vector<std::size_t>& walls,
                      std::pair<LineRef, LineRef> l, double diameter) {
  const Plan& plan = scene.plan();
  return decide_written([&](auto tag) {
    using NT = decltype(tag);
    const NT r = NT(diameter) / NT(2);
    const auto p = crossing(line_of<NT>(plan.walls[l.first.wall], l.first, r),
                            line_of<NT>(plan.walls[l.second.wall], l.second, r));
    if (!p) return false;
    for (const std::size_t w : walls)
      if (is_nearer_than(*p, wall_polygon<NT>(plan, scene.joins(), w), r * r)) return false;
    return true;
  });
}

Point2 centroid(const std::vector<Point2>& outline) {
  double a2 = 0, cx = 0, cy = 0;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Point2 p = outline[k], q = outline[(k + 1) % outline.size()];
    const double w = p.x * q.y - p.y * q.x;
    a2 += w, cx += (p.x + q.x) * w, cy += (p.y + q.y) * w;
  }
  return a2 != 0 ? Point2{cx / (3 * a2), cy / (3 * a2)} : outline.front();
}

}  // namespace

StoreyWalls::StoreyWalls(const Scene& scene, const std::vector<std::size_t>& walls)
    : scene_(scene), member_(scene.plan().walls.size(), false), quads_(scene.plan().walls.size()) {
  for (const std::size_t w : walls) {
    if (!scene.is_usable(w)) continue;
    member_[w] = true;
    quads_[w] = detail::approximate_footprint(scene.plan(), scene.joins(), w);
  }
}

std::vector<std::size_t> StoreyWalls::near(const Box2& box) const {
  std::vector<std::size_t> out = scene_.walls_near(box);
  std::erase_if(out, [&](std::size_t w) { return !member_[w]; });
  return out;
}

double StoreyWalls::clearance(Point2 p, const std::vector<std::size_t>& walls) const {
  double best = INFINITY;
  for (const std::size_t w : walls) best = std::min(best, distance_to_quad(p, quads_[w]));
  return best;
}

FreeDisc find_free_disc(const StoreyWalls& sw, const std::vector<Room>& rooms,
                        const RoomLocator& locator, std::size_t room, double diameter) {
  const Room& r = rooms[room];
  if (r.outline.size() < 3) return {};
  const double rho = diameter / 2;
  const std::vector<std::size_t> walls = sw.near(grown(room_box(r), rho + kSlack));
  const Box2 box = room_box(r);
  const double tol = 1e-9 * (1 + std::max({std::fabs(box.min_x), std::fabs(box.max_x),
                                           std::fabs(box.min_y), std::fabs(box.max_y)}));
  const Point2 middle = centroid(r.outline);
  if (locator.locate(middle) == room && sw.clearance(middle, walls) > rho + tol &&
      is_clear(sw.scene(), walls, middle, diameter))
    return {true, middle, sw.clearance(middle, walls)};
  // Corners of the centres kSlack farther from the walls: clear by kSlack, so the intervals
  // verify them at once. Only a circle that fits with less to spare needs the exact rebuild.
  for (const DiscCentre& c : candidates(sw, walls, locator, room, rho + kSlack, tol))
    if (c.clearance >= rho + kSlack / 2 && is_clear(sw.scene(), walls, c.p, diameter))
      return {true, c.p, c.clearance};
  const std::vector<DiscCentre> touching = candidates(sw, walls, locator, room, rho, tol);
  for (std::size_t k = 0; k < touching.size() && k < kVerified; ++k) {
    const DiscCentre& c = touching[k];
    if (c.lines && is_clear_rebuilt(sw.scene(), walls, *c.lines, diameter))
      return {true, c.p, c.clearance};
  }
  if (touching.empty()) return {false, middle, sw.clearance(middle, walls)};
  return {false, touching.front().p, touching.front().clearance};
}

double largest_free_diameter(const StoreyWalls& sw, const std::vector<Room>& rooms,
                             const RoomLocator& locator, std::size_t room, double diameter) {
  const Room& r = rooms[room];
  const std::vector<std::size_t> walls = sw.near(grown(room_box(r), diameter));
  double lo = 0, hi = diameter;
  for (int i = 0; i < 12; ++i) {  // on the candidates in doubles: an estimate for messages
    const double mid = (lo + hi) / 2;
    (candidates(sw, walls, locator, room, mid / 2, 0.0).empty() ? hi : lo) = mid;
  }
  return lo;
}

}  // namespace roomcad::rules
