// SPDX-License-Identifier: GPL-3.0-or-later
// Moving, turning and scaling objects and whole plans through homogeneous matrices
// (plan/transform2d.h); what each quantity does is in plan/plan_edit.h.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

#include "plan/plan_edit.h"
#include "plan/plan_objects.h"
#include "plan/transform2d.h"

namespace roomcad {
namespace {

/// How one plan transform acts on each kind of quantity.
struct PlanMap {
  std::array<Transform2d, 3> points;  ///< positions: T(-centre), linear part, T(centre)
  Transform2d directions;             ///< the rotation alone: directions ignore moves and scales
  double length_factor = 1.0;         ///< lengths along a wall
};

double scaled(double length, double factor) {
  return exact_dot(std::array{length}, std::array{factor});
}

Point2 map_point(const PlanMap& map, Point2 p) { return apply_exactly(map.points, p); }

Vec3 map_position(const PlanMap& map, Vec3 v) {
  const Point2 p = map_point(map, {v.x, v.y});
  return {p.x, p.y, v.z};
}

Vec3 map_direction(const Transform2d& t, Vec3 v) {
  const Point2 d = apply_to_direction(t, {v.x, v.y});
  return {d.x, d.y, v.z};
}

void map_wall(Wall& wall, const PlanMap& map) {
  wall.from = map_point(map, wall.from);
  wall.to = map_point(map, wall.to);
}

/// A slab's outline and holes go through the map; its top and thickness are vertical sizes.
void map_slab(Slab& slab, const PlanMap& map) {
  for (Point2& p : slab.outline) p = map_point(map, p);
  for (Polygon& hole : slab.holes)
    for (Point2& p : hole) p = map_point(map, p);
}

/// Scales the along-wall lengths of the openings hosted by `wall_id`, or of all openings
/// without one (a whole-plan map: one pass, not one per wall).
void map_openings(Plan& plan, std::optional<std::string_view> wall_id, const PlanMap& map) {
  if (map.length_factor == 1.0) return;
  for (Opening& o : plan.openings) {
    if (wall_id && o.wall != *wall_id) continue;
    o.offset = scaled(o.offset, map.length_factor);
    o.width = scaled(o.width, map.length_factor);
  }
}

void map_camera(Camera& camera, const PlanMap& map) {
  camera.eye = map_position(map, camera.eye);
  camera.target = map_position(map, camera.target);
  camera.up = map_direction(map.directions, camera.up);
}

void map_obstruction(Obstruction& obstruction, const PlanMap& map) {
  for (Point2& p : obstruction.outline) p = map_point(map, p);
}

void map_room(RoomLabel& room, const PlanMap& map) { room.at = map_point(map, room.at); }

void map_light(Light& light, const PlanMap& map) {
  light.direction = map_direction(map.directions, light.direction);
}

/// Turns the site's north with the plan, when the site says where north is (a plan that does not
/// keeps its default). A mirror mirrors it.
void map_north(Site& site, const PlanMap& map) {
  if (!site.north && !site.location) return;
  const double turn = site.north.value_or(0.0) * std::numbers::pi / 180.0;
  const Point2 d = apply_to_direction(map.directions, {-std::sin(turn), std::cos(turn)});
  double degrees = std::atan2(-d.x, d.y) * 180.0 / std::numbers::pi;
  // A quarter turn gives 90 degrees, not 89.99999999999999.
  if (const double whole = std::round(degrees); std::fabs(degrees - whole) < 1e-9) degrees = whole;
  site.north = degrees == 0.0 ? 0.0 : degrees;  // no -0
}

/// Maps the site's rectangle when the map keeps it axis-aligned (moves, scales, quarter
/// turns): the new origin is the low corner of the mapped corners. Else leaves it.
void map_site(Site& site, const PlanMap& map) {
  const auto& m = map.points[1].m;  // the linear part
  const bool keeps_axes = m[0][1] == 0.0 && m[1][0] == 0.0;
  const bool swaps_axes = m[0][0] == 0.0 && m[1][1] == 0.0;
  if (!keeps_axes && !swaps_axes) return;
  const Point2 far{
      exact_dot(std::array{site.origin.x, double(site.cells[0])}, std::array{1.0, site.cell_size}),
      exact_dot(std::array{site.origin.y, double(site.cells[1])}, std::array{1.0, site.cell_size})};
  const Point2 a = map_point(map, site.origin);
  const Point2 b = map_point(map, far);
  site.origin = {std::min(a.x, b.x), std::min(a.y, b.y)};
  if (swaps_axes) std::swap(site.cells[0], site.cells[1]);
  site.cell_size = scaled(site.cell_size, map.length_factor);
}

Point2 midpoint(Point2 a, Point2 b) {
  return {exact_dot(std::array{a.x, b.x}, std::array{0.5, 0.5}),
          exact_dot(std::array{a.y, b.y}, std::array{0.5, 0.5})};
}

Point2 site_centre(const Site& s) {
  const double half = s.cell_size / 2.0;  // exact in binary, and the shortest decimal halves too
  return {exact_dot(std::array{s.origin.x, double(s.cells[0])}, std::array{1.0, half}),
          exact_dot(std::array{s.origin.y, double(s.cells[1])}, std::array{1.0, half})};
}

/// The default centre of a turn or scale of one object: a wall's midpoint, a slab's first
/// corner, a room's point, a camera's target.
Point2 default_centre(const Plan& plan, ObjectRef ref) {
  if (ref.kind == ObjectKind::wall)
    return midpoint(plan.walls[ref.index].from, plan.walls[ref.index].to);
  if (ref.kind == ObjectKind::slab && !plan.slabs[ref.index].outline.empty())
    return plan.slabs[ref.index].outline.front();
  if (ref.kind == ObjectKind::obstruction && !plan.obstructions[ref.index].outline.empty())
    return plan.obstructions[ref.index].outline.front();
  if (ref.kind == ObjectKind::room) return plan.rooms[ref.index].at;
  if (ref.kind == ObjectKind::camera)
    return {plan.cameras[ref.index].target.x, plan.cameras[ref.index].target.y};
  return {};
}

/// Applies `map` to one object; `verb` names the edit in errors.
EditSummary map_object(Plan& plan, ObjectRef ref, const PlanMap& map, std::string_view verb) {
  const Plan before = plan;
  switch (ref.kind) {
    case ObjectKind::wall:
      map_wall(plan.walls[ref.index], map);
      map_openings(plan, plan.walls[ref.index].id, map);
      break;
    case ObjectKind::slab: map_slab(plan.slabs[ref.index], map); break;
    case ObjectKind::obstruction: map_obstruction(plan.obstructions[ref.index], map); break;
    case ObjectKind::room: map_room(plan.rooms[ref.index], map); break;
    case ObjectKind::camera: map_camera(plan.cameras[ref.index], map); break;
    case ObjectKind::light: map_light(plan.lights[ref.index], map); break;
    case ObjectKind::level:
      throw PreconditionError(fmt::format(
          "{}: '{}' is a level, which has no position in plan; {} its walls and slabs, or the "
          "whole plan with --all",
          verb, plan.levels[ref.index].id, verb));
    case ObjectKind::opening:
      throw PreconditionError(fmt::format(
          "{}: '{}' is an opening; it goes with its wall '{}' (move it along the wall with "
          "`move --by du`, resize it with `set`)",
          verb, plan.openings[ref.index].id, plan.openings[ref.index].wall));
  }
  return changed_objects(before, plan);
}

EditSummary map_everything(Plan& plan, const PlanMap& map) {
  const Plan before = plan;
  for (Wall& w : plan.walls) map_wall(w, map);
  for (Slab& s : plan.slabs) map_slab(s, map);
  for (Obstruction& o : plan.obstructions) map_obstruction(o, map);
  for (RoomLabel& r : plan.rooms) map_room(r, map);
  map_openings(plan, std::nullopt, map);
  for (Camera& c : plan.cameras) map_camera(c, map);
  for (Light& l : plan.lights) map_light(l, map);
  map_site(plan.site, map);
  map_north(plan.site, map);
  return changed_objects(before, plan);
}

void require_finite(double value, std::string_view verb, std::string_view what) {
  if (!std::isfinite(value))
    throw PreconditionError(
        fmt::format("{}: {} must be a finite number, got {}", verb, what, value));
}

void require_factor(double factor) {
  require_finite(factor, "scale", "the factor");
  if (factor <= 0.0)
    throw PreconditionError(fmt::format("scale: the factor must be positive, got {}", factor));
}

void require_not_light(const Plan& plan, ObjectRef ref, std::string_view verb) {
  if (ref.kind == ObjectKind::light)
    throw PreconditionError(
        fmt::format("{}: light '{}' is directional and has no position; turn it with `rotate`",
                    verb, plan.lights[ref.index].id));
}

PlanMap translation_map(Point2 by) {
  require_finite(by.x, "move", "--by dx");
  require_finite(by.y, "move", "--by dy");
  return {{identity_transform(), identity_transform(), translate(by.x, by.y)},
          identity_transform(),
          1.0};
}

PlanMap rotation_map(double degrees, Point2 about) {
  require_finite(degrees, "rotate", "the angle");
  return {about_point(rotate(degrees), about), rotate(degrees), 1.0};
}

PlanMap scale_map(double factor, Point2 about) {
  require_factor(factor);
  return {about_point(scale(factor), about), identity_transform(), factor};
}

}  // namespace

EditSummary changed_objects(const Plan& before, const Plan& after) {
  EditSummary summary;
  if (before.site != after.site) summary.changed.push_back("site");
  const auto compare = [&](const auto& old_objects, const auto& new_objects) {
    for (std::size_t i = 0; i < old_objects.size(); ++i)
      if (old_objects[i] != new_objects[i]) summary.changed.push_back(new_objects[i].id);
  };
  compare(before.levels, after.levels);
  compare(before.walls, after.walls);
  compare(before.openings, after.openings);
  compare(before.slabs, after.slabs);
  compare(before.rooms, after.rooms);
  compare(before.lights, after.lights);
  compare(before.cameras, after.cameras);
  return summary;
}

EditSummary move_object(Plan& plan, std::string_view id, Point2 by) {
  const ObjectRef ref = require_object(plan, id, "move");
  require_not_light(plan, ref, "move");
  return map_object(plan, ref, translation_map(by), "move");
}

EditSummary slide_opening(Plan& plan, std::string_view id, double du) {
  const ObjectRef ref = require_object(plan, id, "move");
  if (ref.kind != ObjectKind::opening)
    throw PreconditionError(fmt::format(
        "move: {} '{}' moves in the plan: give --by dx,dy (one number moves an opening along "
        "its wall)",
        kind_name(plan, ref), id));
  require_finite(du, "move", "--by du");
  Opening& opening = plan.openings[ref.index];
  const double offset = exact_add(opening.offset, du);
  EditSummary summary;
  if (offset != opening.offset) summary.changed.push_back(opening.id);
  opening.offset = offset;
  return summary;
}

EditSummary rotate_object(Plan& plan, std::string_view id, double degrees,
                          std::optional<Point2> about) {
  const ObjectRef ref = require_object(plan, id, "rotate");
  return map_object(plan, ref, rotation_map(degrees, about.value_or(default_centre(plan, ref))),
                    "rotate");
}

EditSummary scale_object(Plan& plan, std::string_view id, double factor,
                         std::optional<Point2> about) {
  const ObjectRef ref = require_object(plan, id, "scale");
  require_not_light(plan, ref, "scale");
  return map_object(plan, ref, scale_map(factor, about.value_or(default_centre(plan, ref))),
                    "scale");
}

EditSummary move_all(Plan& plan, Point2 by) { return map_everything(plan, translation_map(by)); }

EditSummary rotate_all(Plan& plan, double degrees, std::optional<Point2> about) {
  return map_everything(plan, rotation_map(degrees, about.value_or(site_centre(plan.site))));
}

EditSummary scale_all(Plan& plan, double factor, std::optional<Point2> about) {
  return map_everything(plan, scale_map(factor, about.value_or(site_centre(plan.site))));
}

}  // namespace roomcad
