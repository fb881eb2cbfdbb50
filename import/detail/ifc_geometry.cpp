// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/ifc_geometry.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace roomcad::ifc {
namespace {

using step::Value;

Vec add(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec scale(Vec a, double k) { return {a.x * k, a.y * k, a.z * k}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
std::optional<Vec> unit(Vec a) {
  const double n = std::sqrt(dot(a, a));
  if (!(n > 0.0) || !std::isfinite(n)) return std::nullopt;
  return scale(a, 1.0 / n);
}

/// The orthonormal frame of a z axis and an approximate x axis (IFC's placement rule).
Transform frame(Vec origin, Vec z, Vec x) {
  const Vec zz = unit(z).value_or(Vec{0, 0, 1});
  std::optional<Vec> xx = unit(add(x, scale(zz, -dot(x, zz))));
  if (!xx) {  // x along z: any perpendicular will do
    const Vec helper = std::abs(zz.z) < 0.9 ? Vec{0, 0, 1} : Vec{1, 0, 0};
    xx = unit(cross(helper, zz));
  }
  return {{*xx, cross(zz, *xx), zz}, origin};
}

constexpr int kMaxNesting =
    16;  ///< mapped items, clippings and placements nested deeper are refused

constexpr double kPi = 3.14159265358979323846;

/// @return `a` in [0, 2 pi).
double turn(double a) {
  a = std::fmod(a, 2 * kPi);
  return a < 0.0 ? a + 2 * kPi : a;
}

/// @return the point `p` in the coordinates of the orthonormal frame `t`.
Vec local(const Transform& t, Vec p) {
  const Vec d = add(p, scale(t.origin, -1.0));
  return {dot(d, t.axes[0]), dot(d, t.axes[1]), dot(d, t.axes[2])};
}

/// Appends the points of the arc of circle (centre c, radius r, in the xy plane of `to_plane`)
/// from angle a0 turning by `sweep` radians, without its first point, as chords whose
/// sagitta is at most `sagitta`.
void append_arc(Vec c, double r, double a0, double sweep, double sagitta, const Transform& to_plane,
                std::vector<Vec>& out) {
  const double step = r > sagitta ? 2 * std::acos(1.0 - sagitta / r) : kPi / 2;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / step)));
  for (int i = 1; i <= n; ++i) {
    const double a = a0 + sweep * i / n;
    out.push_back(to_plane.apply({c.x + r * std::cos(a), c.y + r * std::sin(a), c.z}));
  }
}

/// @return the coordinates of a list value (an IfcCartesianPointList's entry).
std::optional<Vec> coordinates(const Value& v) {
  if (v.items.size() < 2 || !v.items[0].is_number() || !v.items[1].is_number()) return std::nullopt;
  return Vec{v.items[0].number, v.items[1].number,
             v.items.size() > 2 && v.items[2].is_number() ? v.items[2].number : 0.0};
}

/// @return the 1-based indices of an IfcLineIndex or IfcArcIndex value.
std::vector<std::size_t> indices(const Value& v) {
  const std::vector<Value>& list =
      v.items.size() == 1 && v.items[0].kind == Value::Kind::list ? v.items[0].items : v.items;
  std::vector<std::size_t> out;
  for (const Value& i : list)
    if (i.is_number() && i.number >= 1.0) out.push_back(static_cast<std::size_t>(i.number));
  return out;
}

}  // namespace

bool Clip::bounds(Vec q) const {
  if (boundary.empty()) return true;
  const Transform t = frame(boundary.front(), boundary_axis, {1, 0, 0});
  const Vec p = local(t, q);
  bool inside = false;
  for (std::size_t i = 0, j = boundary.size() - 1; i < boundary.size(); j = i++) {
    const Vec a = local(t, boundary[i]);
    const Vec b = local(t, boundary[j]);
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
  }
  return inside;
}

std::vector<double> Clip::crossings(Vec a, Vec b) const {
  std::vector<double> out;
  if (boundary.empty()) return out;
  const Transform t = frame(boundary.front(), boundary_axis, {1, 0, 0});
  const Vec p = local(t, a);
  const Vec r = add(local(t, b), scale(p, -1.0));
  for (std::size_t i = 0, j = boundary.size() - 1; i < boundary.size(); j = i++) {
    const Vec q = local(t, boundary[j]);
    const Vec e = add(local(t, boundary[i]), scale(q, -1.0));
    const double den = r.x * e.y - r.y * e.x;
    if (den == 0.0) continue;
    const double along = ((q.x - p.x) * e.y - (q.y - p.y) * e.x) / den;
    const double on_edge = ((q.x - p.x) * r.y - (q.y - p.y) * r.x) / den;
    if (along > 0.0 && along < 1.0 && on_edge >= 0.0 && on_edge <= 1.0) out.push_back(along);
  }
  return out;
}

bool Clip::removes(Vec q) const {
  return dot(add(q, scale(point, -1.0)), removed) > 0.0 && bounds(q);
}

Vec Transform::apply(Vec p) const { return add(origin, rotate(p)); }

Vec Transform::rotate(Vec v) const {
  return add(add(scale(axes[0], v.x), scale(axes[1], v.y)), scale(axes[2], v.z));
}

Transform Transform::after(const Transform& inner) const {
  return {{rotate(inner.axes[0]), rotate(inner.axes[1]), rotate(inner.axes[2])},
          apply(inner.origin)};
}

std::string name_of(const step::Instance& e) { return fmt::format("#{} {}", e.id, e.type); }

const step::Instance* Geometry::get(const Value& v) const {
  return v.kind == Value::Kind::ref ? file_.find(v.id) : nullptr;
}

const Value& Geometry::param(const step::Instance& e, std::size_t i) {
  static const Value kNull{};
  return i < e.parameters.size() ? e.parameters[i] : kNull;
}

const step::Instance* Geometry::unit_of(const char* kind) const {
  for (const step::Instance& e : file_.instances) {
    if (e.type != "IFCUNITASSIGNMENT") continue;
    for (const Value& u : param(e, 0).items)
      if (const step::Instance* unit = get(u); unit && param(*unit, 1).text == kind) return unit;
  }
  return nullptr;
}

std::optional<double> Geometry::conversion_factor(const step::Instance& unit) const {
  const step::Instance* m = get(param(unit, 3));
  if (unit.type != "IFCCONVERSIONBASEDUNIT" || !m) return std::nullopt;
  const Value& factor = param(*m, 0);
  const Value& number =
      factor.kind == Value::Kind::typed && !factor.items.empty() ? factor.items[0] : factor;
  if (!number.is_number() || !(number.number > 0.0)) return std::nullopt;
  const step::Instance* si = get(param(*m, 1));
  return number.number * (si && param(*si, 2).text == "MILLI" ? 1e-3 : 1.0);
}

double Geometry::metres_per_unit() const {
  const step::Instance* u = unit_of("LENGTHUNIT");
  if (!u) return 1.0;
  if (u->type == "IFCSIUNIT") {
    const std::string& prefix = param(*u, 2).text;
    return prefix == "MILLI"   ? 1e-3
           : prefix == "CENTI" ? 1e-2
           : prefix == "DECI"  ? 1e-1
           : prefix == "KILO"  ? 1e3
                               : 1.0;
  }
  return conversion_factor(*u).value_or(1.0);  // feet, inches: a factor times an SI unit
}

std::optional<Vec> Geometry::point(const Value& v) const {
  const step::Instance* p = get(v);
  if (!p || p->type != "IFCCARTESIANPOINT") return std::nullopt;
  const auto& c = param(*p, 0).items;
  if (c.size() < 2 || !c[0].is_number() || !c[1].is_number()) return std::nullopt;
  return Vec{c[0].number, c[1].number, c.size() > 2 && c[2].is_number() ? c[2].number : 0.0};
}

std::optional<Vec> Geometry::direction(const Value& v) const {
  const step::Instance* d = get(v);
  if (!d || d->type != "IFCDIRECTION") return std::nullopt;
  const auto& c = param(*d, 0).items;
  if (c.size() < 2 || !c[0].is_number() || !c[1].is_number()) return std::nullopt;
  return unit(Vec{c[0].number, c[1].number, c.size() > 2 && c[2].is_number() ? c[2].number : 0.0});
}

Transform Geometry::axis_placement(const Value& v) const {
  const step::Instance* a = get(v);
  if (!a) return {};
  const Vec origin = point(param(*a, 0)).value_or(Vec{});
  if (a->type == "IFCAXIS2PLACEMENT2D") {
    const Vec x = direction(param(*a, 1)).value_or(Vec{1, 0, 0});
    return frame(origin, {0, 0, 1}, x);
  }
  if (a->type != "IFCAXIS2PLACEMENT3D") return {.origin = origin};
  return frame(origin, direction(param(*a, 1)).value_or(Vec{0, 0, 1}),
               direction(param(*a, 2)).value_or(Vec{1, 0, 0}));
}

Transform Geometry::placement(const Value& object_placement) {
  const step::Instance* p = get(object_placement);
  if (!p || p->type != "IFCLOCALPLACEMENT" || depth_ > kMaxNesting) return {};
  if (const auto it = placements_.find(p->id); it != placements_.end()) return it->second;
  ++depth_;
  const Transform parent = placement(param(*p, 0));
  --depth_;
  const Transform world = parent.after(axis_placement(param(*p, 1)));
  placements_.emplace(p->id, world);
  return world;
}

const step::Instance* Geometry::representation(const step::Instance& product,
                                               const char* identifier) const {
  const step::Instance* shape = get(param(product, 6));
  if (!shape) return nullptr;
  for (const Value& r : param(*shape, 2).items) {
    const step::Instance* rep = get(r);
    if (rep && param(*rep, 1).text == identifier) return rep;
  }
  return nullptr;
}

std::optional<AxisCurve> Geometry::axis(const step::Instance& product) {
  const step::Instance* rep = representation(product, "Axis");
  if (!rep || param(*rep, 3).items.empty()) return std::nullopt;
  const step::Instance* line = get(param(*rep, 3).items[0]);
  if (!line) return std::nullopt;
  const Transform world = placement(param(product, 5));
  const step::Instance* circle = line->type == "IFCTRIMMEDCURVE" ? get(param(*line, 0)) : nullptr;
  std::vector<Vec> points;
  std::vector<std::string> problems;
  if (!chain(*line, world, points, problems, 0) || points.size() < 2) return std::nullopt;
  AxisCurve out{.from = points.front(), .to = points.back()};
  if (circle && circle->type == "IFCCIRCLE") {
    // The turn is the chords' (their sum of signed angles), which mirroring in the placement
    // reverses as it does the arc.
    const Transform c = world.after(axis_placement(param(*circle, 0)));
    double turned = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      const Vec p = local(c, points[i - 1]);
      const Vec q = local(c, points[i]);
      turned += std::atan2(p.x * q.y - p.y * q.x, p.x * q.x + p.y * q.y);
    }
    const Vec z = cross(c.axes[0], c.axes[1]);
    out.arc_extent = (z.z < 0.0 ? -turned : turned) * 180.0 / kPi;
    out.centre = c.origin;
    out.radius = param(*circle, 1).number;
  } else if (points.size() != 2) {
    return std::nullopt;
  }
  return out;
}

std::vector<Prism> Geometry::body(const step::Instance& product,
                                  std::vector<std::string>& problems) {
  std::vector<Prism> out;
  const step::Instance* rep = representation(product, "Body");
  if (!rep) {
    problems.push_back("it has no 'Body' representation");
    return out;
  }
  const Transform world = placement(param(product, 5));
  for (const Value& item : param(*rep, 3).items)
    if (const step::Instance* i = get(item)) add_item(*i, world, out, problems, 0);
  return out;
}

Transform Geometry::operator_3d(const step::Instance& op) const {
  // IfcCartesianTransformationOperator3D(Axis1, Axis2, LocalOrigin, Scale, Axis3).
  const Vec origin = point(param(op, 2)).value_or(Vec{});
  const double k = param(op, 3).is_number() ? param(op, 3).number : 1.0;
  Transform t = frame(origin, direction(param(op, 4)).value_or(Vec{0, 0, 1}),
                      direction(param(op, 0)).value_or(Vec{1, 0, 0}));
  for (Vec& a : t.axes) a = scale(a, k);
  return t;
}

void Geometry::add_item(const step::Instance& item, const Transform& to_world,
                        std::vector<Prism>& out, std::vector<std::string>& problems, int depth) {
  if (depth > kMaxNesting) {
    problems.push_back(fmt::format("{} nests deeper than {}", name_of(item), kMaxNesting));
    return;
  }
  if (item.type == "IFCEXTRUDEDAREASOLID") {
    const Transform position = to_world.after(axis_placement(param(item, 1)));
    const auto dir = direction(param(item, 2));
    const step::Instance* area = get(param(item, 0));
    if (!dir || !area || !param(item, 3).is_number()) {
      problems.push_back(fmt::format("{} has no valid profile, direction or depth", name_of(item)));
      return;
    }
    if (std::optional<Prism> p = profile(*area, position, problems)) {
      p->sweep = scale(position.rotate(*dir), param(item, 3).number);
      out.push_back(std::move(*p));
    }
  } else if (item.type == "IFCMAPPEDITEM") {
    const step::Instance* source = get(param(item, 0));
    const step::Instance* target = get(param(item, 1));
    const step::Instance* mapped = source ? get(param(*source, 1)) : nullptr;
    if (!mapped || !target) {
      problems.push_back(fmt::format("{} maps no representation", name_of(item)));
      return;
    }
    const Transform t =
        to_world.after(operator_3d(*target)).after(axis_placement(param(*source, 0)));
    for (const Value& v : param(*mapped, 3).items)
      if (const step::Instance* i = get(v)) add_item(*i, t, out, problems, depth + 1);
  } else if (item.type == "IFCBOOLEANCLIPPINGRESULT" || item.type == "IFCBOOLEANRESULT") {
    const step::Instance* second = get(param(item, 2));
    const std::optional<Clip> clip = second && param(item, 0).text == "DIFFERENCE"
                                         ? half_space(*second, to_world)
                                         : std::nullopt;
    if (!clip)
      problems.push_back(
          fmt::format("{} ({} of its body and another solid) is imported as its "
                      "first operand, unclipped",
                      name_of(item), param(item, 0).text));
    const std::size_t before = out.size();
    if (const step::Instance* first = get(param(item, 1)))
      add_item(*first, to_world, out, problems, depth + 1);
    if (clip)
      for (std::size_t i = before; i < out.size(); ++i) out[i].clips.push_back(*clip);
  } else {
    problems.push_back(
        fmt::format("{} is not an extrusion (the importer reads IfcExtrudedAreaSolid, "
                    "mapped or clipped)",
                    name_of(item)));
  }
}

std::optional<Prism> Geometry::profile(const step::Instance& p, const Transform& to_plane,
                                       std::vector<std::string>& problems) const {
  Prism out;
  if (p.type == "IFCRECTANGLEPROFILEDEF") {
    const Value& x = param(p, 3);
    const Value& y = param(p, 4);
    if (!x.is_number() || !y.is_number()) return std::nullopt;
    const Transform at = to_plane.after(axis_placement(param(p, 2)));
    const double hx = x.number / 2;
    const double hy = y.number / 2;
    for (const Vec c : {Vec{-hx, -hy, 0}, Vec{hx, -hy, 0}, Vec{hx, hy, 0}, Vec{-hx, hy, 0}})
      out.outer.push_back(at.apply(c));
    out.rectangle = true;
    return out;
  }
  if (p.type == "IFCCIRCLEPROFILEDEF") {  // a round opening: its circle as chords
    const Value& r = param(p, 3);
    if (!r.is_number() || !(r.number > 0.0)) return std::nullopt;
    const Transform at = to_plane.after(axis_placement(param(p, 2)));
    out.outer.push_back(at.apply({r.number, 0.0, 0.0}));
    append_arc({}, r.number, 0.0, 2 * kPi, sagitta_, at, out.outer);
    out.outer.pop_back();  // the first point again
    out.chord_error = kChordSagitta;
    return out;
  }
  if (p.type != "IFCARBITRARYCLOSEDPROFILEDEF" && p.type != "IFCARBITRARYPROFILEDEFWITHVOIDS") {
    problems.push_back(
        fmt::format("{} is not a rectangle, circle or curve-bounded profile", name_of(p)));
    return std::nullopt;
  }
  arcs_ = false;
  const step::Instance* outer = get(param(p, 2));
  auto ring = outer ? curve(*outer, to_plane, problems) : std::nullopt;
  if (!ring) return std::nullopt;
  out.outer = std::move(*ring);
  for (const Value& h : param(p, 3).items) {
    const step::Instance* inner = get(h);
    if (auto hole = inner ? curve(*inner, to_plane, problems) : std::nullopt)
      out.holes.push_back(std::move(*hole));
  }
  if (arcs_) out.chord_error = kChordSagitta;
  return out;
}

std::optional<std::vector<Vec>> Geometry::curve(const step::Instance& c, const Transform& to_plane,
                                                std::vector<std::string>& problems) const {
  std::vector<Vec> ring;
  if (!chain(c, to_plane, ring, problems, 0)) return std::nullopt;
  // Closed curves repeat their first point (and composite segments share their ends).
  std::vector<Vec> clean;
  for (const Vec& v : ring) {
    if (!clean.empty() && std::abs(v.x - clean.back().x) + std::abs(v.y - clean.back().y) +
                                  std::abs(v.z - clean.back().z) <=
                              1e-12)
      continue;
    clean.push_back(v);
  }
  while (clean.size() > 1 && std::abs(clean.front().x - clean.back().x) +
                                     std::abs(clean.front().y - clean.back().y) +
                                     std::abs(clean.front().z - clean.back().z) <=
                                 1e-12)
    clean.pop_back();
  if (clean.size() < 3) {
    problems.push_back(fmt::format("{} has fewer than 3 distinct points", name_of(c)));
    return std::nullopt;
  }
  return clean;
}

bool Geometry::chain(const step::Instance& c, const Transform& to_plane, std::vector<Vec>& out,
                     std::vector<std::string>& problems, int depth) const {
  if (depth > kMaxNesting) {
    problems.push_back(fmt::format("{} nests deeper than {}", name_of(c), kMaxNesting));
    return false;
  }
  if (c.type == "IFCPOLYLINE") {
    for (const Value& v : param(c, 0).items)
      if (const auto q = point(v)) out.push_back(to_plane.apply(*q));
    return true;
  }
  if (c.type == "IFCINDEXEDPOLYCURVE") {
    const step::Instance* list = get(param(c, 0));
    std::vector<Vec> points;
    for (const Value& v : list ? param(*list, 0).items : std::vector<Value>{})
      if (const auto q = coordinates(v)) points.push_back(*q);
    if (param(c, 1).kind != Value::Kind::list) {  // no segments: one polyline through them all
      for (const Vec& q : points) out.push_back(to_plane.apply(q));
      return true;
    }
    for (const Value& segment : param(c, 1).items) {
      const std::vector<std::size_t> at = indices(segment);
      if (std::any_of(at.begin(), at.end(), [&](std::size_t i) { return i > points.size(); })) {
        problems.push_back(fmt::format("{} indexes a point it does not have", name_of(c)));
        return false;
      }
      if (segment.text == "IFCARCINDEX" && at.size() == 3) {
        out.push_back(to_plane.apply(points[at[0] - 1]));
        arc_through(points[at[0] - 1], points[at[1] - 1], points[at[2] - 1], to_plane, out);
      } else {
        for (const std::size_t i : at) out.push_back(to_plane.apply(points[i - 1]));
      }
    }
    return true;
  }
  if (c.type == "IFCTRIMMEDCURVE") return trimmed_circle(c, to_plane, out, problems);
  if (c.type == "IFCCOMPOSITECURVE") {
    for (const Value& s : param(c, 0).items) {
      const step::Instance* segment = get(s);
      const step::Instance* parent = segment ? get(param(*segment, 2)) : nullptr;
      std::vector<Vec> part;
      if (!parent || !chain(*parent, to_plane, part, problems, depth + 1)) {
        if (!parent) problems.push_back(fmt::format("{} has a segment with no curve", name_of(c)));
        return false;
      }
      if (param(*segment, 1).kind == Value::Kind::enumeration && param(*segment, 1).text == "F")
        std::reverse(part.begin(), part.end());
      out.insert(out.end(), part.begin(), part.end());
    }
    return true;
  }
  problems.push_back(
      fmt::format("{} is not a polyline, indexed poly-curve, trimmed circle or composite of these",
                  name_of(c)));
  return false;
}

bool Geometry::trimmed_circle(const step::Instance& c, const Transform& to_plane,
                              std::vector<Vec>& out, std::vector<std::string>& problems) const {
  const step::Instance* circle = get(param(c, 0));
  if (!circle || circle->type != "IFCCIRCLE" || !param(*circle, 1).is_number() ||
      !(param(*circle, 1).number > 0.0)) {
    problems.push_back(fmt::format("{} does not trim a circle", name_of(c)));
    return false;
  }
  const Transform at = axis_placement(param(*circle, 0));
  const double r = param(*circle, 1).number;
  // A trim is a point on the circle or a parameter (an angle); the point wins when both are.
  auto angle = [&](const Value& trim) -> std::optional<double> {
    std::optional<double> parameter;
    for (const Value& v : trim.items) {
      if (const auto p = point(v)) {
        const Vec q = local(at, *p);
        return std::atan2(q.y, q.x);
      }
      if (v.kind == Value::Kind::typed && !v.items.empty() && v.items[0].is_number())
        parameter = v.items[0].number * radians_per_angle_unit();
    }
    return parameter;
  };
  const auto a0 = angle(param(c, 1));
  const auto a1 = angle(param(c, 2));
  if (!a0 || !a1) {
    problems.push_back(
        fmt::format("{} has a trim that is neither a point nor a parameter", name_of(c)));
    return false;
  }
  const bool sense = param(c, 3).text != "F";
  double sweep = sense ? turn(*a1 - *a0) : -turn(*a0 - *a1);
  if (sweep == 0.0) sweep = sense ? 2 * kPi : -2 * kPi;
  const Transform t = to_plane.after(at);
  out.push_back(t.apply({r * std::cos(*a0), r * std::sin(*a0), 0.0}));
  append_arc({}, r, *a0, sweep, sagitta_, t, out);
  arcs_ = true;
  return true;
}

void Geometry::arc_through(Vec a, Vec m, Vec b, const Transform& to_plane,
                           std::vector<Vec>& out) const {
  // The circumcentre of the three points in their plane (IfcArcIndex: start, a point on the
  // arc, end); three points on a line are a straight segment.
  const double d = 2 * ((a.x - m.x) * (m.y - b.y) - (m.x - b.x) * (a.y - m.y));
  if (std::abs(d) < 1e-12 * (dot(add(a, scale(b, -1)), add(a, scale(b, -1))) + 1e-300)) {
    out.push_back(to_plane.apply(m)), out.push_back(to_plane.apply(b));
    return;
  }
  const double aa = a.x * a.x + a.y * a.y, mm = m.x * m.x + m.y * m.y, bb = b.x * b.x + b.y * b.y;
  const Vec c{(aa * (m.y - b.y) + mm * (b.y - a.y) + bb * (a.y - m.y)) / d,
              (aa * (b.x - m.x) + mm * (a.x - b.x) + bb * (m.x - a.x)) / d, a.z};
  const double r = std::hypot(a.x - c.x, a.y - c.y);
  const double ta = std::atan2(a.y - c.y, a.x - c.x);
  const double ccw = turn(std::atan2(b.y - c.y, b.x - c.x) - ta);
  const double via = turn(std::atan2(m.y - c.y, m.x - c.x) - ta);
  append_arc(c, r, ta, via < ccw ? ccw : ccw - 2 * kPi, sagitta_, to_plane, out);
  arcs_ = true;
}

std::optional<Clip> Geometry::half_space(const step::Instance& h, const Transform& to_world) const {
  if (h.type != "IFCHALFSPACESOLID" && h.type != "IFCBOXEDHALFSPACE" &&
      h.type != "IFCPOLYGONALBOUNDEDHALFSPACE")
    return std::nullopt;
  const step::Instance* plane = get(param(h, 0));
  if (!plane || plane->type != "IFCPLANE") return std::nullopt;
  const Transform at = to_world.after(axis_placement(param(*plane, 0)));
  const auto normal = unit(at.axes[2]);
  if (!normal) return std::nullopt;
  // AgreementFlag true: the half-space's material lies away from the plane's normal.
  Clip clip{.point = at.origin,
            .removed = param(h, 1).text == "T" ? scale(*normal, -1.0) : *normal};
  if (h.type == "IFCPOLYGONALBOUNDEDHALFSPACE") {
    const Transform position = to_world.after(axis_placement(param(h, 2)));
    const step::Instance* boundary = get(param(h, 3));
    std::vector<std::string> problems;
    if (!boundary || !chain(*boundary, position, clip.boundary, problems, 0) ||
        clip.boundary.size() < 3)
      return std::nullopt;
    clip.boundary_axis = unit(position.axes[2]).value_or(Vec{0, 0, 1});
  }
  return clip;
}

std::vector<Vec> Geometry::body_points(const step::Instance& product) {
  std::vector<Vec> out;
  if (const step::Instance* rep = representation(product, "Body")) {
    const Transform world = placement(param(product, 5));
    for (const Value& item : param(*rep, 3).items)
      if (const step::Instance* i = get(item)) add_points(*i, world, out, 0);
  }
  return out;
}

void Geometry::add_points(const step::Instance& item, const Transform& to_world,
                          std::vector<Vec>& out, int depth) {
  if (depth > kMaxNesting) return;
  auto follow = [&](const Value& v, auto&& self) -> void {
    const step::Instance* e = get(v);
    if (!e) {
      for (const Value& i : v.items) self(i, self);
      return;
    }
    if (e->type == "IFCCARTESIANPOINT") {
      if (const auto p = point(v)) out.push_back(to_world.apply(*p));
      return;
    }
    if (e->type == "IFCCARTESIANPOINTLIST3D") {
      for (const Value& c : param(*e, 0).items)
        if (const auto p = coordinates(c)) out.push_back(to_world.apply(*p));
      return;
    }
    // Shells, faces, bounds and loops: their first parameter holds the next level down.
    if (e->type == "IFCCLOSEDSHELL" || e->type == "IFCOPENSHELL" || e->type == "IFCFACE" ||
        e->type == "IFCFACEOUTERBOUND" || e->type == "IFCFACEBOUND" || e->type == "IFCPOLYLOOP")
      self(param(*e, 0), self);
  };
  if (item.type == "IFCFACETEDBREP" || item.type == "IFCPOLYGONALFACESET" ||
      item.type == "IFCSHELLBASEDSURFACEMODEL" || item.type == "IFCFACEBASEDSURFACEMODEL") {
    follow(param(item, 0), follow);
  } else if (item.type == "IFCMAPPEDITEM") {
    const step::Instance* source = get(param(item, 0));
    const step::Instance* target = get(param(item, 1));
    const step::Instance* mapped = source ? get(param(*source, 1)) : nullptr;
    if (!mapped || !target) return;
    const Transform t =
        to_world.after(operator_3d(*target)).after(axis_placement(param(*source, 0)));
    for (const Value& v : param(*mapped, 3).items)
      if (const step::Instance* i = get(v)) add_points(*i, t, out, depth + 1);
  } else if (item.type == "IFCBOOLEANCLIPPINGRESULT" || item.type == "IFCBOOLEANRESULT") {
    if (const step::Instance* first = get(param(item, 1)))
      add_points(*first, to_world, out, depth + 1);
  } else {
    std::vector<std::string> problems;
    std::vector<Prism> prisms;
    add_item(item, to_world, prisms, problems, depth);
    for (const Prism& p : prisms)
      for (const Vec& v : p.outer) out.push_back(v), out.push_back(add(v, p.sweep));
  }
}

double Geometry::radians_per_angle_unit() const {
  const step::Instance* u = unit_of("PLANEANGLEUNIT");
  if (!u || u->type != "IFCCONVERSIONBASEDUNIT") return 1.0;
  return conversion_factor(*u).value_or(kPi / 180.0);
}

}  // namespace roomcad::ifc
