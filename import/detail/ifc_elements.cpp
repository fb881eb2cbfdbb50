// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/ifc_elements.h"

#include "geometry/polygon_predicates.h"
#include "import/detail/ifc_wall_top.h"
#include "plan/signed_area.h"

#include <algorithm>
#include <cmath>
#include <numbers>
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
  std::vector<Clip> clips{};
  double chord_error = 0.0;
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
  Extrusion e{.rectangle = p.rectangle, .clips = p.clips, .chord_error = p.chord_error};
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

/// Says that the arcs of an element's profile are chords, `error` metres from them at most.
void note_chords(ImportState& s, const step::Instance& e, double error,
                 std::vector<std::string> objects = {}) {
  if (error > 0.0)
    s.approximate(e, fmt::format("the arcs of its profile are read as chords within {} m", error),
                  error, std::move(objects));
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
Point2 wall_direction(const Extrusion& x, const std::optional<AxisCurve>& axis, double k,
                      Point2& anchor) {
  if (axis) {
    anchor = {k * axis->from.x, k * axis->from.y};
    const Point2 d{k * (axis->to.x - axis->from.x), k * (axis->to.y - axis->from.y)};
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

/// A wall's centre line and thickness read from its footprint, metres.
struct CentreLine {
  Point2 from{};
  Point2 to{};
  double thickness = 0.0;
  std::optional<double> arc_extent{};
  long inside_corners = 0;  ///< footprint corners between its two sides (straight walls)
};

/// The straight centre line through the middle of the footprint, along the axis if any.
CentreLine straight_line(const ImportState& s, const Extrusion& x,
                         const std::optional<AxisCurve>& axis) {
  Point2 anchor;
  Point2 d = wall_direction(x, axis, s.metres_per_unit, anchor);
  const double dl = std::hypot(d.x, d.y);
  d = {d.x / dl, d.y / dl};
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  for (const Point2& p : x.outer) {
    const Point2 r{p.x - anchor.x, p.y - anchor.y};
    const double u = r.x * d.x + r.y * d.y;
    const double v = d.x * r.y - d.y * r.x;
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  if (axis) u0 = 0.0, u1 = dl;
  const double vc = (v0 + v1) / 2;
  CentreLine c;
  c.from = {s.metres(anchor.x + u0 * d.x - vc * d.y), s.metres(anchor.y + u0 * d.y + vc * d.x)};
  c.to = {s.metres(anchor.x + u1 * d.x - vc * d.y), s.metres(anchor.y + u1 * d.y + vc * d.x)};
  c.thickness = s.metres(v1 - v0);
  // Ends cut square, mitred or back to a wall they meet are what the plan's joins make again;
  // a corner of the footprint between its two sides (a notch, an L) is not.
  c.inside_corners = std::count_if(x.outer.begin(), x.outer.end(), [&](const Point2& p) {
    const double v = d.x * (p.y - anchor.y) - d.y * (p.x - anchor.x);
    return v - v0 > 1e-6 && v1 - v > 1e-6;
  });
  return c;
}

/// The arc centre line of an axis that is a trimmed circle: through the middle of the
/// footprint's radii about the axis's centre, from and to the axis's end angles.
CentreLine arc_line(const ImportState& s, const Extrusion& x, const AxisCurve& axis) {
  const double k = s.metres_per_unit;
  const Point2 c{k * axis.centre.x, k * axis.centre.y};
  double r0 = INFINITY, r1 = 0.0;
  for (const Point2& p : x.outer)
    r0 = std::min(r0, std::hypot(p.x - c.x, p.y - c.y)),
    r1 = std::max(r1, std::hypot(p.x - c.x, p.y - c.y));
  const double r = (r0 + r1) / 2;
  auto on_centre_line = [&](const Vec& end) -> Point2 {
    const double a = std::atan2(k * end.y - c.y, k * end.x - c.x);
    return {s.metres(c.x + r * std::cos(a)), s.metres(c.y + r * std::sin(a))};
  };
  return {.from = on_centre_line(axis.from),
          .to = on_centre_line(axis.to),
          .thickness = s.metres(r1 - r0),
          .arc_extent = std::round(*axis.arc_extent * 1e9) / 1e9};
}

/// Adds the wall `w` as the pieces of top `t` along its centre line (straight walls).
void add_pieces(ImportState& s, const step::Instance& e, const Wall& w, const WallTop& t) {
  const double elevation = w.level.empty() ? 0.0 : s.elevation_of_level.at(w.level);
  const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
  const Point2 d{(w.to.x - w.from.x) / length, (w.to.y - w.from.y) / length};
  std::vector<std::string> ids;
  std::vector<std::size_t>& pieces = s.walls_of[e.id];
  for (std::size_t i = 0; i < t.pieces.size(); ++i) {
    const TopPiece& p = t.pieces[i];
    Wall piece = w;
    if (i > 0) piece.id = s.unique_id(fmt::format("{} ({})", w.id, i + 1), "wall", e.id);
    piece.from = {s.metres(w.from.x + d.x * p.from), s.metres(w.from.y + d.y * p.from)};
    piece.to = {s.metres(w.from.x + d.x * p.to), s.metres(w.from.y + d.y * p.to)};
    piece.base = s.metres(t.bottom - elevation);
    piece.height = s.metres(p.top_from - t.bottom);
    if (const double end = s.metres(p.top_to - t.bottom); end != piece.height)
      piece.height_at_end = end;
    ids.push_back(piece.id);
    pieces.push_back(s.plan.walls.size());
    s.plan.walls.push_back(std::move(piece));
  }
  for (const std::string& note : t.notes) s.approximate(e, note, t.error, ids);
}

/// Adds the wall `w` as the pieces of its clipped top: one wall, or several split where the
/// clipping planes over it meet.
void add_clipped_wall(ImportState& s, const step::Instance& e, Wall w, const Extrusion& x) {
  if (w.arc_extent) {  // clippings of arc walls are not followed
    if (!x.clips.empty())
      s.warn(Code::import_approximated, e,
             "it is an arc wall clipped by half-spaces; it is imported unclipped", {w.id});
    w.base = s.metres(x.bottom - (w.level.empty() ? 0.0 : s.elevation_of_level.at(w.level)));
    w.height = s.metres(x.depth);
    s.walls_of[e.id].push_back(s.plan.walls.size());
    s.plan.walls.push_back(std::move(w));
    return;
  }
  WallTop t = clipped_top(w.from, w.to, w.thickness, x.bottom, x.bottom + x.depth, x.clips,
                          s.metres_per_unit);
  if (t.pieces.size() > 1)
    t.notes.push_back(
        fmt::format("its clipped top is {} planes (a gable, a hip); it is "
                    "imported as {} walls split where they meet",
                    t.pieces.size(), t.pieces.size()));
  add_pieces(s, e, w, t);
}

/// Reads a wall whose body is an upright profile swept horizontally across it.
void import_upright_wall(ImportState& s, const step::Instance& e, const Prism& body) {
  std::string why;
  const std::optional<UprightWall> u = upright_wall(body, s.metres_per_unit, why);
  if (!u) return s.warn(Code::import_skipped_element, e, "not imported: " + why);
  Wall w;
  w.from = {s.metres(u->from.x), s.metres(u->from.y)};
  w.to = {s.metres(u->to.x), s.metres(u->to.y)};
  w.thickness = s.metres(u->thickness);
  w.id = s.unique_id(Geometry::param(e, 2).text, "wall", e.id);
  const auto level = s.level_of_element.find(e.id);
  w.level = level == s.level_of_element.end() ? "" : level->second;
  if (!body.clips.empty())
    s.warn(Code::import_approximated, e,
           "it is an upright profile clipped by half-spaces; it is imported unclipped", {w.id});
  note_chords(s, e, body.chord_error, {w.id});
  s.read.insert(e.id);
  add_pieces(s, e, w, u->top);
}

void import_wall(ImportState& s, const step::Instance& e,
                 const std::unordered_map<std::uint32_t, std::uint32_t>& usages) {
  const std::optional<Prism> body = single_body(s, e, "wall");
  if (!body) return;
  std::string why{};
  const std::optional<Extrusion> x = vertical(s, *body, why);
  if (!x) return import_upright_wall(s, e, *body);
  const auto axis = s.geometry.axis(e);
  const CentreLine line =
      axis && axis->arc_extent ? arc_line(s, *x, *axis) : straight_line(s, *x, axis);
  Wall w;
  w.from = line.from, w.to = line.to, w.thickness = line.thickness;
  w.arc_extent = line.arc_extent;
  if (!(w.thickness > 0.0) || w.from == w.to)
    return s.warn(Code::import_zero_length_wall, e,
                  "not imported: its footprint has no length or thickness");
  w.id = s.unique_id(Geometry::param(e, 2).text, "wall", e.id);
  const auto level = s.level_of_element.find(e.id);
  w.level = level == s.level_of_element.end() ? "" : level->second;
  if (line.inside_corners > 0)
    s.warn(
        Code::import_approximated, e,
        fmt::format("its footprint has {} corners between its two sides (it is not a straight wall "
                    "with cut ends); it is imported as the rectangle of its centre line and "
                    "thickness",
                    line.inside_corners),
        {w.id});
  note_chords(s, e, x->chord_error, {w.id});
  if (!x->holes.empty())
    s.warn(Code::import_approximated, e,
           fmt::format("its profile has {} voids; the wall is imported solid", x->holes.size()),
           {w.id});
  if (const auto layers = layer_thickness(s, usages, e.id);
      layers && std::abs(*layers - w.thickness) > 1e-3)
    s.approximate(e,
                  fmt::format("its material layers add up to {} m but its body is {} m thick; "
                              "the body's thickness is imported",
                              *layers, w.thickness),
                  0.0, {w.id});
  s.read.insert(e.id);
  add_clipped_wall(s, e, std::move(w), *x);
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

/// Where an opening's body lies on a wall: metres along its centre line from `from` (around
/// the circle for an arc wall) and world heights.
struct Extent {
  double u0 = INFINITY, u1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  double length = 0.0;  ///< of the wall's centre line
  bool box = true;      ///< every point at u0 or u1 and at z0 or z1: a box across the wall
  [[nodiscard]] double overlap() const { return std::min(u1, length) - std::max(u0, 0.0); }
};

/// @return the points of an opening's body: its prism's corners, or for a body that is not an
///   extrusion the points of its faces.
std::vector<Vec> opening_points(ImportState& s, const step::Instance& e,
                                const std::optional<Prism>& body) {
  if (!body) return s.geometry.body_points(e);
  std::vector<Vec> out;
  for (const Vec& v : body->outer)
    out.push_back(v),
        out.push_back({v.x + body->sweep.x, v.y + body->sweep.y, v.z + body->sweep.z});
  return out;
}

Extent extent_on(const Wall& wall, const std::vector<Vec>& points, double k) {
  Extent x;
  const Point2 chord{wall.to.x - wall.from.x, wall.to.y - wall.from.y};
  const double c = std::hypot(chord.x, chord.y);
  const Point2 d{chord.x / c, chord.y / c};
  // An arc wall: its circle's centre lies left of the chord for a counter-clockwise sweep.
  const double sweep = wall.arc_extent.value_or(0.0) * std::numbers::pi / 180.0;
  const double radius = sweep != 0.0 ? c / (2 * std::sin(std::abs(sweep) / 2)) : 0.0;
  const double off = (sweep > 0.0 ? 1.0 : -1.0) * radius * std::cos(std::abs(sweep) / 2);
  const Point2 centre{(wall.from.x + wall.to.x) / 2 - d.y * off,
                      (wall.from.y + wall.to.y) / 2 + d.x * off};
  x.length = sweep != 0.0 ? radius * std::abs(sweep) : c;
  auto along = [&](double px, double py) {
    if (sweep == 0.0) return (px - wall.from.x) * d.x + (py - wall.from.y) * d.y;
    const Point2 a{wall.from.x - centre.x, wall.from.y - centre.y};
    const Point2 b{px - centre.x, py - centre.y};
    const double angle = std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
    return radius * (sweep > 0.0 ? angle : -angle);
  };
  for (const Vec& q : points) {
    const double u = along(k * q.x, k * q.y);
    x.u0 = std::min(x.u0, u), x.u1 = std::max(x.u1, u), x.z0 = std::min(x.z0, k * q.z),
    x.z1 = std::max(x.z1, k * q.z);
  }
  for (const Vec& q : points) {
    const double u = along(k * q.x, k * q.y);
    x.box = x.box && (std::abs(u - x.u0) < 1e-6 || std::abs(u - x.u1) < 1e-6) &&
            (std::abs(k * q.z - x.z0) < 1e-6 || std::abs(k * q.z - x.z1) < 1e-6);
  }
  return x;
}

/// Adds the part of an opening (extent `x`) that lies in wall `wall_index`. @return false when
/// it does not cut the wall.
bool add_opening_part(ImportState& s, const step::Instance& e, std::size_t wall_index,
                      const Extent& x, const Filling& fill, std::string_view name) {
  const Wall& wall = s.plan.walls[wall_index];
  const double base = wall.base + (wall.level.empty() ? 0.0 : s.elevation_of_level.at(wall.level));
  const double c0 = std::max(x.u0, 0.0), c1 = std::min(x.u1, x.length);
  const double top = std::min(wall.height, wall.height_at_end.value_or(wall.height));
  const double s0 = std::max(x.z0 - base, 0.0), s1 = std::min(x.z1 - base, top);
  if (!(c1 - c0 > 1e-6) || !(s1 - s0 > 1e-6)) return false;
  Opening o;
  const step::Instance* named = fill.element ? fill.element : &e;
  o.id = s.unique_id(name, "opening", named->id);
  o.wall = wall.id;
  o.offset = s.metres(c0), o.width = s.metres(c1 - c0), o.sill = s.metres(s0),
  o.height = s.metres(s1 - s0);
  const double cut = std::max({s0 - (x.z0 - base), (x.z1 - base) - s1, 0.0});
  if (cut > 1e-6)
    s.approximate(
        e, fmt::format("it reaches above or below wall '{}'; it is cut to the wall", wall.id), cut,
        {o.id});
  if (fill.element && fill.element->type.starts_with("IFCWINDOW")) {
    o.type = OpeningType::window;
  } else if (fill.element && fill.element->type.starts_with("IFCDOOR")) {
    o.type = OpeningType::door;
    if (Geometry::param(*fill.element, 11).text.find("RIGHT") != std::string::npos)
      o.hinge = Hinge::right;
  } else {
    o.type = o.sill > 0.0 ? OpeningType::window : OpeningType::door;
    s.approximate(
        e, fmt::format("no door or window fills it; it is imported as a {}", to_string(o.type)),
        0.0, {o.id});
  }
  s.plan.openings.push_back(std::move(o));
  return true;
}

void import_opening(ImportState& s, const step::Instance& e,
                    const std::vector<std::size_t>& wall_pieces, const Filling& fill) {
  std::vector<std::string> problems{};
  std::vector<Prism> prisms = s.geometry.body(e, problems);
  const std::optional<Prism> body =
      prisms.empty() ? std::nullopt : std::optional<Prism>(std::move(prisms.front()));
  const std::vector<Vec> points = opening_points(s, e, body);
  if (points.empty())
    return s.warn(
        Code::import_skipped_opening, e,
        fmt::format("not imported: {}", problems.empty() ? "its body is empty" : problems.front()));
  const double k = s.metres_per_unit;
  std::vector<std::pair<std::size_t, Extent>> parts;
  for (const std::size_t i : wall_pieces)
    if (Extent x = extent_on(s.plan.walls[i], points, k); x.overlap() > 1e-6)
      parts.emplace_back(i, x);
  if (parts.empty())
    parts.emplace_back(wall_pieces.front(),
                       extent_on(s.plan.walls[wall_pieces.front()], points, k));
  if (body) {
    for (const std::string& p : problems) s.warn(Code::import_approximated, e, p);
    note_chords(s, e, body->chord_error);
    if (prisms.size() > 1)
      s.warn(Code::import_approximated, e,
             fmt::format("its body has {} solids; the opening is imported as the first",
                         prisms.size()));
  } else {
    const bool box =
        std::all_of(parts.begin(), parts.end(), [](const auto& p) { return p.second.box; });
    if (box)
      s.approximate(e, "its body is a box of faces, not an extrusion; it is imported as that box",
                    0.0);
    else
      s.warn(Code::import_approximated, e,
             "its body is not an extrusion; it is imported as its extent along the wall and in "
             "height");
  }
  // Beyond the wall's ends (or its pieces' outer ends) the opening is cut to the wall.
  const Extent& first = parts.front().second;
  const Extent& last = parts.back().second;
  const double beyond = std::max({-first.u0, last.u1 - last.length, 0.0});
  if (beyond > 1e-6)
    s.approximate(e,
                  fmt::format("it reaches beyond wall '{}'; it is cut to the wall",
                              s.plan.walls[parts.front().first].id),
                  beyond);
  const step::Instance* named = fill.element ? fill.element : &e;
  const std::string& name = Geometry::param(*named, 2).text;
  bool added = false;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Extent x = parts[i].second;
    if (i > 0) x.u0 = std::max(x.u0, 0.0);
    if (i + 1 < parts.size()) x.u1 = std::min(x.u1, x.length);
    added |= add_opening_part(s, e, parts[i].first, x, fill,
                              i == 0 || name.empty() ? name : fmt::format("{} ({})", name, i + 1));
  }
  if (!added)
    return s.warn(Code::import_skipped_opening, e,
                  fmt::format("not imported: it does not cut wall '{}'",
                              s.plan.walls[parts.front().first].id));
  if (parts.size() > 1)
    s.approximate(e,
                  fmt::format("it spans the {} walls its wall is split into; it is imported as "
                              "one opening in each",
                              parts.size()),
                  0.0);
  if (fill.element) s.handled.insert(fill.element->id), s.read.insert(fill.element->id);
  s.read.insert(e.id);
  const Wall& wall = s.plan.walls[parts.front().first];
  if (body && parts.size() == 1 && !wall.arc_extent) {
    const double base =
        wall.base + (wall.level.empty() ? 0.0 : s.elevation_of_level.at(wall.level));
    const double length = std::hypot(wall.to.x - wall.from.x, wall.to.y - wall.from.y);
    set_shape(s.plan.openings.back(), *body, k, wall.from,
              {(wall.to.x - wall.from.x) / length, (wall.to.y - wall.from.y) / length}, base);
  }
}

/// @return the ring in metres as the plan writes them, counter-clockwise.
Polygon counter_clockwise(const ImportState& s, std::vector<Point2> ring) {
  for (Point2& p : ring) p = {s.metres(p.x), s.metres(p.y)};
  if (signed_area(ring) < 0.0) std::reverse(ring.begin(), ring.end());
  return ring;
}

/// Reads an opening voiding an imported slab as a hole in it.
void import_slab_opening(ImportState& s, const step::Instance& e, std::size_t slab_index) {
  const std::optional<Prism> body = single_body(s, e, "opening");
  if (!body) return;
  std::string why;
  const std::optional<Extrusion> x = vertical(s, *body, why);
  Slab& slab = s.plan.slabs[slab_index];
  if (!x)
    return s.warn(
        Code::import_skipped_opening, e,
        fmt::format("not imported: {} (a hole in slab '{}' is a vertical prism)", why, slab.id));
  const Polygon hole = counter_clockwise(s, x->outer);
  const bool clear = std::all_of(slab.holes.begin(), slab.holes.end(),
                                 [&](const Polygon& h) { return are_disjoint(hole, h); });
  if (!is_simple_polygon(hole) || !is_strictly_inside(hole, slab.outline) || !clear)
    return s.warn(Code::import_skipped_opening, e,
                  fmt::format("not imported: its footprint is not strictly inside slab '{}' "
                              "and clear of its other holes",
                              slab.id));
  // A hole goes through the slab's whole thickness; a recess that does not is read as one.
  const double top = slab.top + (slab.level.empty() ? 0.0 : s.elevation_of_level.at(slab.level));
  const double short_by =
      std::max(0.0, x->bottom - (top - slab.thickness)) + std::max(0.0, top - x->bottom - x->depth);
  if (short_by > 1e-6)
    s.approximate(e,
                  fmt::format("it does not go through the whole of slab '{}'; it is imported as "
                              "a hole through it",
                              slab.id),
                  std::min(short_by, slab.thickness), {slab.id});
  s.read.insert(e.id);
  slab.holes.push_back(hole);
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
  add_warning(code, entity, what, std::move(objects));
  if (code == Code::import_approximated)
    approximated.try_emplace(entity.id, 0.0), unmeasured.insert(entity.id);
  else skipped.insert(entity.id);
}

void ImportState::approximate(const step::Instance& entity, std::string_view what, double metres,
                              std::vector<std::string> objects) {
  add_warning(Code::import_approximated, entity, what, std::move(objects));
  double& largest = approximated[entity.id];
  largest = std::max(largest, metres);
}

void ImportState::add_warning(Code code, const step::Instance& entity, std::string_view what,
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
    if (const auto slab = s.slab_of.find(Geometry::param(rel, 4).id); slab != s.slab_of.end()) {
      import_slab_opening(s, *opening, slab->second);
      continue;
    }
    const auto wall = s.walls_of.find(Geometry::param(rel, 4).id);
    if (wall == s.walls_of.end()) {
      s.warn(Code::import_skipped_opening, *opening,
             fmt::format("not imported: the element it voids (#{}) is not an imported wall "
                         "or slab",
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
    slab.outline = counter_clockwise(s, x->outer);
    for (auto& hole : x->holes) slab.holes.push_back(counter_clockwise(s, hole));
    if (!x->clips.empty())
      s.warn(Code::import_approximated, e, "it is clipped by half-spaces; it is imported unclipped",
             {slab.id});
    note_chords(s, e, x->chord_error, {slab.id});
    s.read.insert(e.id);
    s.slab_of.emplace(e.id, s.plan.slabs.size());
    s.plan.slabs.push_back(std::move(slab));
  }
}

}  // namespace roomcad::ifc
