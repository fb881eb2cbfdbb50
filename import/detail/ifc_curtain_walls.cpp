// SPDX-License-Identifier: GPL-3.0-or-later
// Curtain walls (IfcCurtainWall with its IfcMember mullions and IfcPlate panels) as the plan's
// walls: a straight wall over the footprint of its parts, as high as they reach, as thick as
// its mullions (or kCurtainThickness), holding the doors and windows among its parts as openings.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "import/detail/ifc_elements.h"

namespace roomcad::ifc {
namespace {

using step::Value;

constexpr double kCurtainThickness = 0.1;  ///< metres, for parts with no depth

/// The aggregated parts of each element (IfcRelAggregates: RelatingObject -> RelatedObjects).
std::unordered_map<std::uint32_t, std::vector<const step::Instance*>> parts_of(
    const ImportState& s) {
  std::unordered_map<std::uint32_t, std::vector<const step::Instance*>> out;
  for (const step::Instance& rel : s.file.instances) {
    if (rel.type != "IFCRELAGGREGATES") continue;
    for (const Value& v : Geometry::param(rel, 5).items)
      if (const step::Instance* part = s.geometry.get(v))
        out[Geometry::param(rel, 4).id].push_back(part);
  }
  return out;
}

/// A line through points: a point on it and its unit direction, the principal axis of the
/// points' spread in plan.
std::pair<Point2, Point2> principal_line(const std::vector<Point2>& points) {
  Point2 c{0.0, 0.0};
  for (const Point2& p : points) c = {c.x + p.x, c.y + p.y};
  c = {c.x / static_cast<double>(points.size()), c.y / static_cast<double>(points.size())};
  double xx = 0.0, xy = 0.0, yy = 0.0;
  for (const Point2& p : points)
    xx += (p.x - c.x) * (p.x - c.x), xy += (p.x - c.x) * (p.y - c.y),
        yy += (p.y - c.y) * (p.y - c.y);
  const double angle = 0.5 * std::atan2(2 * xy, xx - yy);
  return {c, {std::cos(angle), std::sin(angle)}};
}

/// Reads a door or window among a curtain wall's parts as an opening of `wall`.
void add_part_opening(ImportState& s, const step::Instance& part, const Wall& wall,
                      double wall_bottom) {
  const double k = s.metres_per_unit;
  const double length = std::hypot(wall.to.x - wall.from.x, wall.to.y - wall.from.y);
  const Point2 d{(wall.to.x - wall.from.x) / length, (wall.to.y - wall.from.y) / length};
  double u0 = INFINITY, u1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  for (const Vec& v : s.geometry.body_points(part)) {
    const double u = (k * v.x - wall.from.x) * d.x + (k * v.y - wall.from.y) * d.y;
    u0 = std::min(u0, u), u1 = std::max(u1, u), z0 = std::min(z0, k * v.z),
    z1 = std::max(z1, k * v.z);
  }
  u0 = std::max(u0, 0.0), u1 = std::min(u1, length);
  z0 = std::max(z0 - wall_bottom, 0.0), z1 = std::min(z1 - wall_bottom, wall.height);
  if (!(u1 - u0 > 1e-6) || !(z1 - z0 > 1e-6))
    return s.warn(Code::import_skipped_opening, part,
                  fmt::format("not imported: its body does not lie in curtain wall '{}'", wall.id));
  Opening o;
  o.id = s.unique_id(Geometry::param(part, 2).text, "opening", part.id);
  o.wall = wall.id;
  o.type = part.type.starts_with("IFCDOOR") ? OpeningType::door : OpeningType::window;
  o.offset = s.metres(u0), o.width = s.metres(u1 - u0), o.sill = s.metres(z0),
  o.height = s.metres(z1 - z0);
  s.read.insert(part.id), s.handled.insert(part.id);
  s.plan.openings.push_back(std::move(o));
}

void import_curtain_wall(ImportState& s, const step::Instance& e,
                         const std::vector<const step::Instance*>& parts) {
  const double k = s.metres_per_unit;
  std::vector<Vec> points = s.geometry.body_points(e);
  std::size_t members = 0, plates = 0;
  for (const step::Instance* part : parts) {
    if (part->type != "IFCMEMBER" && part->type != "IFCPLATE") continue;
    const std::vector<Vec> more = s.geometry.body_points(*part);
    points.insert(points.end(), more.begin(), more.end());
    (part->type == "IFCMEMBER" ? members : plates) += 1;
  }
  if (points.size() < 2)
    return s.warn(Code::import_skipped_element, e,
                  "not imported: neither it nor its members and plates have a body");
  std::vector<Point2> plan;
  double z0 = INFINITY, z1 = -INFINITY;
  for (const Vec& v : points)
    plan.push_back({k * v.x, k * v.y}), z0 = std::min(z0, k * v.z), z1 = std::max(z1, k * v.z);
  const auto [c, d] = principal_line(plan);
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  for (const Point2& p : plan) {
    const double u = (p.x - c.x) * d.x + (p.y - c.y) * d.y;
    const double v = d.x * (p.y - c.y) - d.y * (p.x - c.x);
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  const double vc = (v0 + v1) / 2;
  Wall w;
  w.from = {s.metres(c.x + u0 * d.x - vc * d.y), s.metres(c.y + u0 * d.y + vc * d.x)};
  w.to = {s.metres(c.x + u1 * d.x - vc * d.y), s.metres(c.y + u1 * d.y + vc * d.x)};
  w.thickness = v1 - v0 > 1e-3 ? s.metres(v1 - v0) : kCurtainThickness;
  w.height = s.metres(z1 - z0);
  if (w.from == w.to || !(w.height > 0.0))
    return s.warn(Code::import_zero_length_wall, e,
                  "not imported: its members and plates have no length or height");
  w.id = s.unique_id(Geometry::param(e, 2).text, "curtain-wall", e.id);
  const auto level = s.level_of_element.find(e.id);
  w.level = level == s.level_of_element.end() ? "" : level->second;
  w.base = s.metres(z0 - (w.level.empty() ? 0.0 : s.elevation_of_level.at(w.level)));
  w.color = {0xa8, 0xc8, 0xd8};
  s.warn(Code::import_approximated, e,
         fmt::format("a curtain wall is imported as a solid wall {} m thick over the footprint "
                     "and height of its {} members and {} plates",
                     w.thickness, members, plates),
         {w.id});
  s.read.insert(e.id);
  for (const step::Instance* part : parts) {
    if (part->type != "IFCMEMBER" && part->type != "IFCPLATE") continue;
    s.handled.insert(part->id), s.read.insert(part->id);
    s.approximated.try_emplace(part->id, 0.0), s.unmeasured.insert(part->id);
  }
  s.walls_of[e.id].push_back(s.plan.walls.size());
  s.plan.walls.push_back(w);
  for (const step::Instance* part : parts)
    if (part->type.starts_with("IFCDOOR") || part->type.starts_with("IFCWINDOW"))
      add_part_opening(s, *part, w, z0);
}

}  // namespace

void import_curtain_walls(ImportState& s) {
  const auto parts = parts_of(s);
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCCURTAINWALL") continue;
    ++s.walls;
    s.handled.insert(e.id);
    const auto it = parts.find(e.id);
    import_curtain_wall(s, e,
                        it == parts.end() ? std::vector<const step::Instance*>{} : it->second);
  }
}

}  // namespace roomcad::ifc
