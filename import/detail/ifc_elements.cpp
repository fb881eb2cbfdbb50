// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/ifc_elements.h"
#include "plan/signed_area.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace roomcad::ifc {
namespace {

using step::Value;

constexpr double kFlat = 1e-6;  ///< relative slope below which an extrusion counts as vertical

/// A vertical extrusion of a horizontal profile, in metres: its outline, holes, bottom and depth.
struct Extrusion {
  std::vector<Point2> outer{};
  std::vector<std::vector<Point2>> holes{};
  double bottom = 0.0;
  double depth = 0.0;
  bool rectangle = false;
};

/// @return the prism as a vertical extrusion, or a sentence saying why it is not one.
std::optional<Extrusion> vertical(const ImportState& s, const Prism& p, std::string& why) {
  const double length =
      std::sqrt(p.sweep.x * p.sweep.x + p.sweep.y * p.sweep.y + p.sweep.z * p.sweep.z);
  if (!(length > 0.0) || std::hypot(p.sweep.x, p.sweep.y) > kFlat * length) {
    why = "its body is not extruded vertically";
    return std::nullopt;
  }
  const double z = p.outer.front().z;
  Extrusion e{.rectangle = p.rectangle};
  for (const Vec& v : p.outer) {
    if (std::abs(v.z - z) > kFlat * std::max(1.0, length)) {
      why = "its profile is not horizontal";
      return std::nullopt;
    }
    e.outer.push_back({s.metres_per_unit * v.x, s.metres_per_unit * v.y});
  }
  for (const auto& hole : p.holes) {
    std::vector<Point2> ring;
    for (const Vec& v : hole) ring.push_back({s.metres_per_unit * v.x, s.metres_per_unit * v.y});
    e.holes.push_back(std::move(ring));
  }
  e.bottom = s.metres_per_unit * (z + std::min(0.0, p.sweep.z));
  e.depth = s.metres_per_unit * std::abs(p.sweep.z);
  return e;
}

/// @return the one prism of the element's body, warning when there are more, or none.
std::optional<Prism> single_body(ImportState& s, const step::Instance& e, std::string_view kind) {
  std::vector<std::string> problems{};
  std::vector<Prism> prisms = s.geometry.body(e, problems);
  if (prisms.empty()) {
    s.warn(
        Code::import_skipped_element, e,
        fmt::format("not imported: {}", problems.empty() ? "its body is empty" : problems.front()));
    return std::nullopt;
  }
  for (const std::string& p : problems) s.warn(Code::import_approximated, e, p);
  if (prisms.size() > 1)
    s.warn(Code::import_approximated, e,
           fmt::format("its body has {} solids; the {} is imported as the first", prisms.size(),
                       kind));
  return std::move(prisms.front());
}

/// The sum of the layer thicknesses of the element's IfcMaterialLayerSetUsage, in metres.
std::optional<double> layer_thickness(
    const ImportState& s, const std::unordered_map<std::uint32_t, std::uint32_t>& usage_of,
    std::uint32_t element) {
  const auto it = usage_of.find(element);
  if (it == usage_of.end()) return std::nullopt;
  const step::Instance* usage = s.file.find(it->second);
  if (!usage || usage->type != "IFCMATERIALLAYERSETUSAGE") return std::nullopt;
  const step::Instance* set = s.geometry.get(Geometry::param(*usage, 0));
  if (!set) return std::nullopt;
  double total = 0.0;
  for (const Value& l : Geometry::param(*set, 0).items) {
    const step::Instance* layer = s.geometry.get(l);
    if (layer && Geometry::param(*layer, 1).is_number()) total += Geometry::param(*layer, 1).number;
  }
  return s.metres_per_unit * total;
}

std::unordered_map<std::uint32_t, std::uint32_t> material_usages(const ImportState& s) {
  std::unordered_map<std::uint32_t, std::uint32_t> out;
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCRELASSOCIATESMATERIAL") continue;
    const Value& material = Geometry::param(e, 5);
    for (const Value& related : Geometry::param(e, 4).items)
      if (related.kind == Value::Kind::ref && material.kind == Value::Kind::ref)
        out.emplace(related.id, material.id);
  }
  return out;
}

/// The wall's centre line direction: the axis, else the footprint's longest edge.
Point2 wall_direction(const Extrusion& x, const std::optional<std::array<Vec, 2>>& axis, double k,
                      Point2& anchor) {
  if (axis) {
    anchor = {k * (*axis)[0].x, k * (*axis)[0].y};
    const Point2 d{k * ((*axis)[1].x - (*axis)[0].x), k * ((*axis)[1].y - (*axis)[0].y)};
    if (std::hypot(d.x, d.y) > 0.0) return d;
  }
  Point2 best{1.0, 0.0};
  double longest = -1.0;
  for (std::size_t i = 0; i < x.outer.size(); ++i) {
    const Point2 a = x.outer[i];
    const Point2 b = x.outer[(i + 1) % x.outer.size()];
    if (std::hypot(b.x - a.x, b.y - a.y) > longest)
      longest = std::hypot(b.x - a.x, b.y - a.y), best = {b.x - a.x, b.y - a.y};
  }
  anchor = x.outer.front();
  return best;
}

void import_wall(ImportState& s, const step::Instance& e,
                 const std::unordered_map<std::uint32_t, std::uint32_t>& usages) {
  const std::optional<Prism> body = single_body(s, e, "wall");
  if (!body) return;
  std::string why{};
  const std::optional<Extrusion> x = vertical(s, *body, why);
  if (!x) return s.warn(Code::import_skipped_element, e, "not imported: " + why);
  const auto axis = s.geometry.axis(e);
  Point2 anchor;
  Point2 d = wall_direction(*x, axis, s.metres_per_unit, anchor);
  const double dl = std::hypot(d.x, d.y);
  d = {d.x / dl, d.y / dl};
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  for (const Point2& p : x->outer) {
    const Point2 r{p.x - anchor.x, p.y - anchor.y};
    const double u = r.x * d.x + r.y * d.y;
    const double v = d.x * r.y - d.y * r.x;
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  if (axis)
    u0 = 0.0,
    u1 = s.metres_per_unit * std::hypot((*axis)[1].x - (*axis)[0].x, (*axis)[1].y - (*axis)[0].y);
  const double vc = (v0 + v1) / 2;
  Wall w;
  w.from = {s.metres(anchor.x + u0 * d.x - vc * d.y), s.metres(anchor.y + u0 * d.y + vc * d.x)};
  w.to = {s.metres(anchor.x + u1 * d.x - vc * d.y), s.metres(anchor.y + u1 * d.y + vc * d.x)};
  w.thickness = s.metres(v1 - v0);
  w.height = s.metres(x->depth);
  if (!(w.thickness > 0.0) || w.from == w.to)
    return s.warn(Code::import_zero_length_wall, e,
                  "not imported: its footprint has no length or thickness");
  w.id = s.unique_id(Geometry::param(e, 2).text, "wall", e.id);
  const auto level = s.level_of_element.find(e.id);
  w.level = level == s.level_of_element.end() ? "" : level->second;
  w.base = s.metres(x->bottom - (w.level.empty() ? 0.0 : s.elevation_of_level.at(w.level)));
  // Ends cut square, mitred or back to a wall they meet are what the plan's joins make again;
  // a corner of the footprint between its two sides (a notch, an L) is not.
  const auto inside = std::count_if(x->outer.begin(), x->outer.end(), [&](const Point2& p) {
    const double v = d.x * (p.y - anchor.y) - d.y * (p.x - anchor.x);
    return v - v0 > 1e-6 && v1 - v > 1e-6;
  });
  if (inside > 0)
    s.warn(
        Code::import_approximated, e,
        fmt::format("its footprint has {} corners between its two sides (it is not a straight wall "
                    "with cut ends); it is imported as the rectangle of its centre line and "
                    "thickness",
                    inside),
        {w.id});
  if (const auto layers = layer_thickness(s, usages, e.id);
      layers && std::abs(*layers - w.thickness) > 1e-3)
    s.warn(Code::import_approximated, e,
           fmt::format("its material layers add up to {} m but its body is {} m thick; the body's "
                       "thickness is imported",
                       *layers, w.thickness),
           {w.id});
  s.wall_of.emplace(e.id, s.plan.walls.size());
  s.plan.walls.push_back(std::move(w));
}

/// The opening's type, from what fills it.
struct Filling {
  const step::Instance* element = nullptr;
};

/// Sets the opening's `shape` from a profile in the wall's plane that is not its rectangle.
void set_shape(Opening& o, const Prism& p, double k, Point2 from, Point2 d, double base) {
  if (p.rectangle || p.holes.size() ||
      std::abs(p.sweep.z) > kFlat * std::hypot(p.sweep.x, p.sweep.y))
    return;
  Polygon shape;
  for (const Vec& v : p.outer) {
    const double u = (k * v.x - from.x) * d.x + (k * v.y - from.y) * d.y;
    shape.push_back({(u - o.offset) / o.width, (k * v.z - base - o.sill) / o.height});
  }
  const double area = signed_area(shape);
  if (std::abs(area) >= 0.999) return;  // the whole rectangle
  if (area < 0.0) std::reverse(shape.begin(), shape.end());
  for (Point2& q : shape) q = {std::round(q.x * 1e6) / 1e6, std::round(q.y * 1e6) / 1e6};
  o.shape = std::move(shape);
}

void import_opening(ImportState& s, const step::Instance& e, std::size_t wall_index,
                    const Filling& fill) {
  const std::optional<Prism> body = single_body(s, e, "opening");
  if (!body) return;
  const Wall& wall = s.plan.walls[wall_index];
  const double k = s.metres_per_unit;
  const double length = std::hypot(wall.to.x - wall.from.x, wall.to.y - wall.from.y);
  const Point2 d{(wall.to.x - wall.from.x) / length, (wall.to.y - wall.from.y) / length};
  const double base = wall.base + (wall.level.empty() ? 0.0 : s.elevation_of_level.at(wall.level));
  double u0 = INFINITY, u1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  for (const Vec& v : body->outer) {
    for (const Vec& q : {v, Vec{v.x + body->sweep.x, v.y + body->sweep.y, v.z + body->sweep.z}}) {
      const double u = (k * q.x - wall.from.x) * d.x + (k * q.y - wall.from.y) * d.y;
      u0 = std::min(u0, u), u1 = std::max(u1, u), z0 = std::min(z0, k * q.z),
      z1 = std::max(z1, k * q.z);
    }
  }
  const double c0 = std::max(u0, 0.0), c1 = std::min(u1, length);
  const double top = wall.height;
  const double s0 = std::max(z0 - base, 0.0), s1 = std::min(z1 - base, top);
  if (!(c1 - c0 > 1e-6) || !(s1 - s0 > 1e-6))
    return s.warn(Code::import_skipped_opening, e,
                  fmt::format("not imported: it does not cut wall '{}'", wall.id));
  Opening o;
  const step::Instance* named = fill.element ? fill.element : &e;
  o.id = s.unique_id(Geometry::param(*named, 2).text, "opening", named->id);
  o.wall = wall.id;
  o.offset = s.metres(c0), o.width = s.metres(c1 - c0), o.sill = s.metres(s0),
  o.height = s.metres(s1 - s0);
  if (c0 - u0 > 1e-6 || u1 - c1 > 1e-6 || s0 - (z0 - base) > 1e-6 || (z1 - base) - s1 > 1e-6)
    s.warn(Code::import_approximated, e,
           fmt::format("it reaches beyond wall '{}'; it is cut to the wall", wall.id), {o.id});
  if (fill.element && fill.element->type.starts_with("IFCWINDOW")) {
    o.type = OpeningType::window;
  } else if (fill.element && fill.element->type.starts_with("IFCDOOR")) {
    o.type = OpeningType::door;
    if (Geometry::param(*fill.element, 11).text.find("RIGHT") != std::string::npos)
      o.hinge = Hinge::right;
  } else {
    o.type = o.sill > 0.0 ? OpeningType::window : OpeningType::door;
    s.warn(Code::import_approximated, e,
           fmt::format("no door or window fills it; it is imported as a {}", to_string(o.type)),
           {o.id});
  }
  if (fill.element) s.handled.insert(fill.element->id);
  set_shape(o, *body, k, wall.from, d, base);
  s.plan.openings.push_back(std::move(o));
}

}  // namespace

std::string ImportState::unique_id(std::string_view name, std::string_view prefix,
                                   std::uint32_t entity) {
  std::string id(name);
  if (id.empty() || ids.contains(id)) id = fmt::format("{}-{}", prefix, entity);
  while (ids.contains(id)) id += "'";
  ids.insert(id);
  return id;
}

void ImportState::warn(Code code, const step::Instance& entity, std::string_view what,
                       std::vector<std::string> objects) {
  handled.insert(entity.id);
  const std::string& name = Geometry::param(entity, 2).text;
  Diagnostic d;
  d.severity = Severity::warning;
  d.code = code;
  d.objects = std::move(objects);
  d.message = fmt::format("{}{}{}{}: {}", name_of(entity), name.empty() ? "" : " '", name,
                          name.empty() ? "" : "'", what);
  warnings.add(std::move(d));
}

double ImportState::metres(double value) const { return std::round(value * 1e6) / 1e6 + 0.0; }

void import_walls(ImportState& s) {
  const auto usages = material_usages(s);
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCWALL" && e.type != "IFCWALLSTANDARDCASE" && e.type != "IFCWALLELEMENTEDCASE")
      continue;
    ++s.walls;
    s.handled.insert(e.id);
    import_wall(s, e, usages);
  }
}

void import_openings(ImportState& s) {
  std::unordered_map<std::uint32_t, Filling> fills;
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCRELFILLSELEMENT") continue;
    fills[Geometry::param(e, 4).id].element = s.geometry.get(Geometry::param(e, 5));
  }
  for (const step::Instance& rel : s.file.instances) {
    if (rel.type != "IFCRELVOIDSELEMENT") continue;
    const step::Instance* opening = s.geometry.get(Geometry::param(rel, 5));
    if (!opening) continue;
    ++s.openings;
    s.handled.insert(opening->id);
    const auto wall = s.wall_of.find(Geometry::param(rel, 4).id);
    if (wall == s.wall_of.end()) {
      s.warn(Code::import_skipped_opening, *opening,
             fmt::format("not imported: the element it voids (#{}) is not an imported wall",
                         Geometry::param(rel, 4).id));
      continue;
    }
    const auto fill = fills.find(opening->id);
    import_opening(s, *opening, wall->second, fill == fills.end() ? Filling{} : fill->second);
  }
}

void import_slabs(ImportState& s) {
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCSLAB" && e.type != "IFCSLABSTANDARDCASE" && e.type != "IFCSLABELEMENTEDCASE")
      continue;
    ++s.slabs;
    s.handled.insert(e.id);
    const std::optional<Prism> body = single_body(s, e, "slab");
    if (!body) continue;
    std::string why;
    std::optional<Extrusion> x = vertical(s, *body, why);
    if (!x) {
      s.warn(Code::import_skipped_element, e, "not imported: " + why);
      continue;
    }
    Slab slab;
    slab.id = s.unique_id(Geometry::param(e, 2).text, "slab", e.id);
    const auto level = s.level_of_element.find(e.id);
    slab.level = level == s.level_of_element.end() ? "" : level->second;
    const double elevation = slab.level.empty() ? 0.0 : s.elevation_of_level.at(slab.level);
    slab.top = s.metres(x->bottom + x->depth - elevation);
    slab.thickness = s.metres(x->depth);
    auto ccw = [&s](std::vector<Point2> ring) {
      for (Point2& p : ring) p = {s.metres(p.x), s.metres(p.y)};
      if (signed_area(ring) < 0.0) std::reverse(ring.begin(), ring.end());
      return ring;
    };
    slab.outline = ccw(x->outer);
    for (auto& hole : x->holes) slab.holes.push_back(ccw(hole));
    s.plan.slabs.push_back(std::move(slab));
  }
}

}  // namespace roomcad::ifc
