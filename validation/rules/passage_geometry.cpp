// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/passage_geometry.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <fmt/format.h>

#include "geometry/broad_phase.h"
#include "validation/detail/diagnostics.h"
#include "validation/rules/door_geometry.h"
#include "validation/rules/fix_search.h"

namespace roomcad::rules {
namespace {

Point2 sub(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
double cross2(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }

Point2 closest_on(Point2 p, Point2 a, Point2 b) {
  const Point2 d = sub(b, a);
  const double len2 = d.x * d.x + d.y * d.y;
  const double t =
      len2 > 0 ? std::clamp(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / len2, 0.0, 1.0) : 0.0;
  return {a.x + t * d.x, a.y + t * d.y};
}

bool inside(Point2 p, const std::vector<Point2>& poly) {
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (cross2(sub(poly[(i + 1) % poly.size()], poly[i]), sub(p, poly[i])) < 0) return false;
  return true;
}

/// The closest points of two convex polygons in doubles; gap 0 when they meet (or nearly).
struct Gap {
  Point2 a, b;
  double d = 0;
};

Gap closest_pair(const std::vector<Point2>& p, const std::vector<Point2>& q) {
  Gap best{p[0], q[0], INFINITY};
  for (const auto& [from, to, flip] : {std::tuple{&p, &q, false}, std::tuple{&q, &p, true}}) {
    for (const Point2& v : *from) {
      if (inside(v, *to)) return {v, v, 0.0};
      for (std::size_t j = 0; j < to->size(); ++j) {
        const Point2 c = closest_on(v, (*to)[j], (*to)[(j + 1) % to->size()]);
        const double d = std::hypot(v.x - c.x, v.y - c.y);
        if (d < best.d) best = flip ? Gap{c, v, d} : Gap{v, c, d};
      }
    }
  }
  return best;
}

/// @return true if p lies in the hole of a door of wall w (with a small tolerance).
bool in_door_hole(const Scene& scene, std::size_t w, Point2 p, double tol) {
  const Wall& wall = scene.plan().walls[w];
  const WallFrame<double> f = wall_frame<double>(wall);
  const double along = (p.x - f.origin.x) * f.u.x + (p.y - f.origin.y) * f.u.y;
  const double across = (p.x - f.origin.x) * f.n.x + (p.y - f.origin.y) * f.n.y;
  if (std::fabs(across) > f.half + tol) return false;
  for (const Span& s : scene.door_holes(w))
    if (along >= s.lo - tol && along <= s.hi + tol) return true;
  return false;
}

template <class NT>
Poly<NT> exact_piece(const Scene& scene, const Piece& piece) {
  return wall_pieces<NT>(scene.plan(), scene.joins(), piece.wall,
                         scene.door_holes(piece.wall))[piece.index];
}

bool closer_than(const Scene& scene, const Piece& p, const Piece& q, double width) {
  return decide_written([&](auto tag) {
    using NT = decltype(tag);
    return is_closer_than(exact_piece<NT>(scene, p), exact_piece<NT>(scene, q),
                          NT(width) * NT(width));
  });
}

std::vector<Piece> pieces_of(const Scene& scene, const std::vector<std::size_t>& walls) {
  std::vector<Piece> out;
  for (const std::size_t w : walls) {
    if (!scene.is_usable(w)) continue;
    const std::vector<Poly<double>> polys =
        wall_pieces<double>(scene.plan(), scene.joins(), w, scene.door_holes(w));
    for (std::size_t k = 0; k < polys.size(); ++k) {
      if (polys[k].n < 3) continue;
      Piece piece{w, k, {}};
      for (std::size_t i = 0; i < polys[k].n; ++i)
        piece.corners.push_back({polys[k][i].x, polys[k][i].y});
      out.push_back(std::move(piece));
    }
  }
  return out;
}

Box2 box_of(const std::vector<Point2>& pts, std::size_t index, double margin) {
  Box2 b{INFINITY, INFINITY, -INFINITY, -INFINITY, index};
  for (const Point2& p : pts) {
    b.min_x = std::min(b.min_x, p.x), b.max_x = std::max(b.max_x, p.x);
    b.min_y = std::min(b.min_y, p.y), b.max_y = std::max(b.max_y, p.y);
  }
  return grown(b, margin);
}

}  // namespace

Outline::Outline(const std::vector<Point2>& points) : points_(points) {
  double total = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    start_.push_back(total);
    const Point2 d = sub(points[(i + 1) % points.size()], points[i]);
    total += std::hypot(d.x, d.y);
  }
}

double Outline::param(Point2 p) const {
  double best = INFINITY, at = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Point2 c = closest_on(p, points_[i], points_[(i + 1) % points_.size()]);
    const double d = std::hypot(p.x - c.x, p.y - c.y);
    if (d < best) best = d, at = start_[i] + std::hypot(c.x - points_[i].x, c.y - points_[i].y);
  }
  return at;
}

Point2 door_face_middle(const Wall& w, const Opening& o, int side) {
  const WallFrame<double> f = wall_frame<double>(w);
  const Pt<double> p = f.at(o.offset + o.width / 2, side == 1 ? f.half : -f.half);
  return {p.x, p.y};
}

PassageGeometry::PassageGeometry(const Scene& scene, const Storey& storey, double width)
    : scene_(scene), storey_(storey), pieces_(pieces_of(scene, storey.walls)) {
  std::vector<Box2> boxes;
  for (std::size_t i = 0; i < pieces_.size(); ++i)
    boxes.push_back(box_of(pieces_[i].corners, i, width / 2 + 1e-6));
  const RoomLocator locator(storey.rooms);
  for (const auto& [p, q] : find_meeting_boxes(boxes))
    if (pieces_[p].wall != pieces_[q].wall) add_barrier(p, q, width, locator);
}

void PassageGeometry::add_barrier(std::size_t p, std::size_t q, double width,
                                  const RoomLocator& locator) {
  const Gap gap = closest_pair(pieces_[p].corners, pieces_[q].corners);
  const Box2 box = box_of(pieces_[p].corners, 0, 0);
  const double tol = 1e-9 * (1 + std::max({std::fabs(box.min_x), std::fabs(box.max_x),
                                           std::fabs(box.min_y), std::fabs(box.max_y)}));
  if (gap.d > width + tol) return;
  if (gap.d >= width - tol && !closer_than(scene_, pieces_[p], pieces_[q], width)) return;
  if (gap.d <= tol && scene_.joins().are_joined(pieces_[p].wall, pieces_[q].wall))
    return;  // a join
  const Point2 mid{(gap.a.x + gap.b.x) / 2, (gap.a.y + gap.b.y) / 2};
  if (in_door_hole(scene_, pieces_[p].wall, mid, tol) ||
      in_door_hole(scene_, pieces_[q].wall, mid, tol))
    return;
  const std::optional<std::size_t> room = locator.locate(mid);
  if (!room) return;
  barriers_.push_back({p, q, gap.a, gap.b, gap.d, *room});
}

}  // namespace roomcad::rules

namespace roomcad::rules {
namespace {

/// @return true if no wall joins wall w at its end e.
bool is_free_end(const Scene& scene, std::size_t w, Point2 e) {
  for (const std::size_t z : scene.walls_near(scene.wall_box(w))) {
    const Join* j = z == w ? nullptr : scene.joins().find(w, z);
    if (j && std::hypot(j->point.x - e.x, j->point.y - e.y) <= 10 * scene.plan().site.tolerance)
      return false;
  }
  return true;
}

struct Candidate {
  std::string text;
  std::vector<FixEdit> edits;
};

/// Shortening wall w at each free end by `step`.
void add_shortenings(const Scene& scene, std::size_t w, double step, std::vector<Candidate>& out) {
  const Wall& wall = scene.plan().walls[w];
  const double length = std::hypot(wall.to.x - wall.from.x, wall.to.y - wall.from.y);
  if (length <= step + 0.05) return;
  const Point2 u{(wall.to.x - wall.from.x) / length, (wall.to.y - wall.from.y) / length};
  if (is_free_end(scene, w, wall.to))
    out.push_back(
        {fmt::format("shorten wall '{}' by {} at its 'to' end", wall.id, detail::metres(step)),
         {set_edit(wall.id,
                   {{"to", point_text({wall.to.x - step * u.x, wall.to.y - step * u.y})}})}});
  if (is_free_end(scene, w, wall.from))
    out.push_back(
        {fmt::format("shorten wall '{}' by {} at its 'from' end", wall.id, detail::metres(step)),
         {set_edit(wall.id,
                   {{"from", point_text({wall.from.x + step * u.x, wall.from.y + step * u.y})}})}});
}

void add_move(const Scene& scene, std::size_t w, Point2 by, double step,
              std::vector<Candidate>& out) {
  std::vector<FixEdit> edits = move_wall_edits(scene, w, by);
  std::string text =
      fmt::format("move wall '{}' {} {}", scene.plan().walls[w].id, detail::metres(step),
                  detail::direction_text({by.x / step, by.y / step}));
  if (edits.size() > 1) text += " with the ends of the walls that meet it";
  out.push_back({std::move(text), std::move(edits)});
}

}  // namespace

std::optional<PassageFix> PassageGeometry::find_fix(const Barrier& bar, double width) const {
  const Plan& plan = scene_.plan();
  const std::size_t x = pieces_[bar.p].wall, y = pieces_[bar.q].wall;
  const double step = centimetres_up(width - bar.gap + 0.01);
  Point2 dir{bar.b.x - bar.a.x, bar.b.y - bar.a.y};
  const double len = std::hypot(dir.x, dir.y);
  if (len == 0) return std::nullopt;  // touching walls: no direction to widen in
  dir = {dir.x / len, dir.y / len};
  std::vector<Candidate> candidates;
  add_shortenings(scene_, x, step, candidates);
  add_shortenings(scene_, y, step, candidates);
  add_move(scene_, y, {dir.x * step, dir.y * step}, step, candidates);
  add_move(scene_, x, {-dir.x * step, -dir.y * step}, step, candidates);
  Box2 box = scene_.wall_box(x);
  const Box2& by = scene_.wall_box(y);
  box = {std::min(box.min_x, by.min_x), std::min(box.min_y, by.min_y),
         std::max(box.max_x, by.max_x), std::max(box.max_y, by.max_y), 0};
  const Neighbourhood near(scene_, grown(box, step + 2.0), heights_of(scene_.plan(), {x, y}));
  const Point2 mid{(bar.a.x + bar.b.x) / 2, (bar.a.y + bar.b.y) / 2};
  for (Candidate& c : candidates) {
    const std::optional<Plan> edited = near.try_edits(c.edits);
    if (!edited) continue;
    const Scene local(*edited);
    const auto lx = local.wall_named(plan.walls[x].id), ly = local.wall_named(plan.walls[y].id);
    if (!lx || !ly || !local.is_usable(*lx) || !local.is_usable(*ly)) continue;
    const std::vector<Piece> px = pieces_of(local, {*lx}), py = pieces_of(local, {*ly});
    bool apart = true;
    for (const Piece& a : px)
      for (const Piece& b : py) apart = apart && !closer_than(local, a, b, width);
    std::vector<std::size_t> usable;
    for (std::size_t w = 0; w < edited->walls.size(); ++w)
      if (local.is_usable(w)) usable.push_back(w);
    if (!apart) continue;
    const std::vector<Room> rooms =
        find_rooms(plan_with_walls(*edited, walls_at_floor(*edited, usable, storey_.floor)));
    if (RoomLocator(rooms).locate(mid)) return PassageFix{std::move(c.text), std::move(c.edits)};
  }
  return std::nullopt;
}

}  // namespace roomcad::rules
