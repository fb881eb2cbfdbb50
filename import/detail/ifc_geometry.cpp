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

}  // namespace

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

double Geometry::metres_per_unit() const {
  for (const step::Instance& e : file_.instances) {
    if (e.type != "IFCUNITASSIGNMENT") continue;
    for (const Value& u : param(e, 0).items) {
      const step::Instance* unit = get(u);
      if (!unit || param(*unit, 1).text != "LENGTHUNIT") continue;
      if (unit->type == "IFCSIUNIT") {
        const std::string& prefix = param(*unit, 2).text;
        return prefix == "MILLI"   ? 1e-3
               : prefix == "CENTI" ? 1e-2
               : prefix == "DECI"  ? 1e-1
               : prefix == "KILO"  ? 1e3
                                   : 1.0;
      }
      if (unit->type == "IFCCONVERSIONBASEDUNIT") {  // feet, inches: a factor times an SI unit
        if (const step::Instance* m = get(param(*unit, 3))) {
          const Value& factor = param(*m, 0);
          const Value& number =
              factor.kind == Value::Kind::typed && !factor.items.empty() ? factor.items[0] : factor;
          double base = 1.0;
          if (const step::Instance* si = get(param(*m, 1)); si && param(*si, 2).text == "MILLI")
            base = 1e-3;
          if (number.is_number() && number.number > 0.0) return number.number * base;
        }
      }
    }
  }
  return 1.0;
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

std::optional<std::array<Vec, 2>> Geometry::axis(const step::Instance& product) {
  const step::Instance* rep = representation(product, "Axis");
  if (!rep || param(*rep, 3).items.empty()) return std::nullopt;
  const step::Instance* line = get(param(*rep, 3).items[0]);
  if (!line || line->type != "IFCPOLYLINE" || param(*line, 0).items.size() != 2)
    return std::nullopt;
  const auto a = point(param(*line, 0).items[0]);
  const auto b = point(param(*line, 0).items[1]);
  if (!a || !b) return std::nullopt;
  const Transform world = placement(param(product, 5));
  return std::array<Vec, 2>{world.apply(*a), world.apply(*b)};
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
    problems.push_back(
        fmt::format("{} ({} of its body and another solid) is imported as its "
                    "first operand, unclipped",
                    name_of(item), param(item, 0).text));
    if (const step::Instance* first = get(param(item, 1)))
      add_item(*first, to_world, out, problems, depth + 1);
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
  if (p.type != "IFCARBITRARYCLOSEDPROFILEDEF" && p.type != "IFCARBITRARYPROFILEDEFWITHVOIDS") {
    problems.push_back(fmt::format("{} is not a rectangle or a polyline profile", name_of(p)));
    return std::nullopt;
  }
  const step::Instance* outer = get(param(p, 2));
  auto ring = outer ? curve(*outer, to_plane, problems) : std::nullopt;
  if (!ring) return std::nullopt;
  out.outer = std::move(*ring);
  for (const Value& h : param(p, 3).items) {
    const step::Instance* inner = get(h);
    if (auto hole = inner ? curve(*inner, to_plane, problems) : std::nullopt)
      out.holes.push_back(std::move(*hole));
  }
  return out;
}

std::optional<std::vector<Vec>> Geometry::curve(const step::Instance& c, const Transform& to_plane,
                                                std::vector<std::string>& problems) const {
  std::vector<Vec> ring;
  if (c.type == "IFCPOLYLINE") {
    for (const Value& v : param(c, 0).items)
      if (const auto q = point(v)) ring.push_back(to_plane.apply(*q));
  } else if (c.type == "IFCINDEXEDPOLYCURVE") {
    const step::Instance* list = get(param(c, 0));
    if (list) {
      for (const Value& v : param(*list, 0).items) {
        if (v.items.size() >= 2 && v.items[0].is_number() && v.items[1].is_number())
          ring.push_back(to_plane.apply(
              {v.items[0].number, v.items[1].number,
               v.items.size() > 2 && v.items[2].is_number() ? v.items[2].number : 0.0}));
      }
    }
    if (param(c, 1).kind == Value::Kind::list)
      problems.push_back(fmt::format("{}: its segments are read as straight lines", name_of(c)));
  } else if (c.type == "IFCCOMPOSITECURVE") {
    for (const Value& s : param(c, 0).items) {
      const step::Instance* segment = get(s);
      const step::Instance* parent = segment ? get(param(*segment, 2)) : nullptr;
      if (!parent || parent->type != "IFCPOLYLINE") {
        problems.push_back(fmt::format("{} has a segment that is not a polyline", name_of(c)));
        return std::nullopt;
      }
      auto part = curve(*parent, to_plane, problems);
      if (!part) return std::nullopt;
      if (param(*segment, 1).kind == Value::Kind::enumeration && param(*segment, 1).text == "F")
        std::reverse(part->begin(), part->end());
      ring.insert(ring.end(), part->begin(), part->end());
    }
  } else {
    problems.push_back(fmt::format("{} is not a polyline", name_of(c)));
    return std::nullopt;
  }
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

}  // namespace roomcad::ifc
