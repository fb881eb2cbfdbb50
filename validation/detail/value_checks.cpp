// SPDX-License-Identifier: GPL-3.0-or-later
// invalid_value: numbers that are not finite, sizes that are not positive, degenerate
// directions, each field judged by its check in the field tables (plan/plan_fields.h); then
// the few rules that tie two fields together. A Plan built in code can hold anything, so
// nothing here is assumed.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "geometry/polygon_predicates.h"
#include "plan/plan_fields.h"
#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"

namespace roomcad::detail {
namespace {

/// Lengths and coordinates that enter exact geometry must lie in the range it is computed in:
/// 0, or a magnitude from 1e-15 m (below a femtometre) to 1e15 m (beyond the solar system).
/// Outside it the exact number types lose their footing (and no plan needs it). Cameras only
/// look, so their positions are merely finite.
bool is_computable(double v) {
  const double m = std::fabs(v);
  return m == 0 || (m >= 1e-15 && m <= 1e15);
}
template <class Object>
constexpr bool kEntersGeometry = !std::is_same_v<Object, Camera>;

/// Checks the fields of one object, reporting each bad one.
class FieldChecker {
 public:
  /// `list` and `index` locate the object ("walls", 3); an empty list means the site.
  FieldChecker(Report& report, std::string_view kind, std::string_view list, std::size_t index,
               std::string_view id)
      : report_(report), kind_(kind), list_(list), index_(index), id_(id) {}

  /// Checks every field of `o` by its table. Texts are only formatted for a bad field:
  /// checking 100,000 good walls formats nothing. @return whether all were good.
  template <class Object>
  bool check_fields(const Object& o) {
    bool all = true;
    for (const Field<Object>& f : fields_of<Object>())
      if (is_present(o, f))
        all =
            std::visit([&](auto member) { return check_value<Object>(f, o.*member); }, f.member) &&
            all;
    return all;
  }

  /// Reports that `field` is `value` and must be `must_be`, with `fix` (or "set <field> to
  /// <must_be>"). @return false, for `good || fail(...)`.
  bool fail(std::string_view field, std::string_view value, std::string_view must_be,
            std::string fix = {}) {
    failed_.emplace_back(field);
    const std::string label = list_.empty()
                                  ? std::string(kind_)
                                  : fmt::format("{} '{}' ({}[{}])", kind_, id_, list_, index_);
    if (fix.empty()) fix = fmt::format("set {} of {} to {}", field, label, must_be);
    report_.add(make_diagnostic(
        Severity::error, Code::invalid_value,
        id_.empty() ? std::vector<std::string>{} : std::vector<std::string>{std::string(id_)},
        fmt::format("{}: {} is {}; it must be {}.", label, field, value, must_be), std::move(fix)));
    return false;
  }

  /// @return the fields reported bad so far ("thickness", "cells[1]", ...).
  [[nodiscard]] const std::vector<std::string>& failed() const { return failed_; }

 private:
  template <class Object>
  bool number_ok(const Field<Object>& f, double v) {
    if (!std::isfinite(v)) return fail(f.name, fmt::format("{}", v), "a finite number");
    if (f.unit == Unit::metre && kEntersGeometry<Object> && !is_computable(v))
      return fail(f.name, fmt::format("{}", v), "0 or between 1e-15 and 1e15 m in size");
    switch (f.check) {
      case Check::positive:
        return v > 0 || fail(f.name, fmt::format("{}", v),
                             fmt::format("a positive number (e.g. {})", f.example));
      case Check::non_negative:
        return v >= 0 || fail(f.name, fmt::format("{}", v), "a number of at least 0");
      case Check::unit_interval:
        return (v >= 0 && v <= 1) || fail(f.name, fmt::format("{}", v), "in [0, 1]");
      case Check::latitude:
        return (v >= -90 && v <= 90) ||
               fail(f.name, fmt::format("{}", v), "a number in [-90, 90] (degrees)");
      case Check::longitude:
        return (v >= -180 && v <= 180) ||
               fail(f.name, fmt::format("{}", v), "a number in [-180, 180] (degrees)");
      case Check::utc_offset:
        return (v >= -12 && v <= 14) ||
               fail(f.name, fmt::format("{}", v), "a number in [-12, 14] (hours)");
      case Check::turn:
        return (v != 0 && std::fabs(v) < 360) ||
               fail(f.name, fmt::format("{}", v), "between -360 and 360 degrees, not 0");
      default: return true;
    }
  }
  bool point_ok(std::string_view name, Point2 p, bool computable) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      return fail(name, fmt::format("[{}, {}]", p.x, p.y), "two finite numbers");
    return !computable || (is_computable(p.x) && is_computable(p.y)) ||
           fail(name, fmt::format("[{}, {}]", p.x, p.y), "0 or between 1e-15 and 1e15 m in size");
  }
  bool polygon_ok(std::string_view name, const Polygon& polygon, bool computable) {
    if (polygon.size() < 3)
      return fail(name, fmt::format("{} corners", polygon.size()),
                  "a polygon of at least 3 corners");
    for (const Point2& p : polygon)
      if (!point_ok(name, p, computable)) return false;
    return true;
  }

  template <class Object>
  bool check_value(const Field<Object>& f, double v) {
    return f.check == Check::lens || number_ok(f, v);
  }
  template <class Object>
  bool check_value(const Field<Object>& f, const std::optional<double>& v) {
    return !v || number_ok(f, *v);
  }
  template <class Object>
  bool check_value(const Field<Object>& f, Point2 p) {
    return point_ok(f.name, p, f.unit == Unit::metre && kEntersGeometry<Object>);
  }
  template <class Object>
  bool check_value(const Field<Object>& f, Vec3 v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      return fail(f.name, fmt::format("[{}, {}, {}]", v.x, v.y, v.z), "three finite numbers");
    return f.check != Check::non_zero || v.x != 0 || v.y != 0 || v.z != 0 ||
           fail(f.name, "[0, 0, 0]", "a non-zero direction");
  }
  template <class Object>
  bool check_value(const Field<Object>& f, const std::string& s) {
    return f.name != "id" || !s.empty() ||
           fail("id", "empty", "a non-empty string unique in the plan");
  }
  template <class Object>
  bool check_value(const Field<Object>& f, const std::array<std::int64_t, 2>& cells) {
    bool ok = true;
    for (int i = 0; i < 2; ++i)
      if (cells[i] <= 0)
        ok = fail(fmt::format("{}[{}]", f.name, i), fmt::format("{}", cells[i]),
                  "a positive whole number of tiles");
    return ok;
  }
  template <class Object>
  bool check_value(const Field<Object>& f, const Polygon& polygon) {
    return polygon_ok(f.name, polygon, f.unit == Unit::metre);
  }
  template <class Object>
  bool check_value(const Field<Object>& f, const std::vector<Polygon>& polygons) {
    bool ok = true;
    for (std::size_t i = 0; i < polygons.size(); ++i)
      ok = polygon_ok(fmt::format("{}[{}]", f.name, i), polygons[i], f.unit == Unit::metre) && ok;
    return ok;
  }
  template <class Object>
  bool check_value(const Field<Object>&, const std::optional<GeoLocation>& location) {
    return !location || check_fields(*location);
  }
  template <class Object, class Other>
  bool check_value(const Field<Object>&, const Other&) {
    return true;  // colours and enums: their type is their check
  }

  Report& report_;
  std::string_view kind_;
  std::string_view list_;
  std::size_t index_;
  std::string_view id_;
  std::vector<std::string> failed_;
};

/// The site's bounds: usable when origin, cells, cell size and maximum height are good (a bad
/// tolerance falls back to 0 in the joins: the bounds still hold).
bool check_site(const Site& s, Report& report) {
  FieldChecker c(report, "site", "", 0, "");
  c.check_fields(s);
  return std::all_of(c.failed().begin(), c.failed().end(), [](const std::string& field) {
    return field == "tolerance" || field == "chord_tolerance" || field == "north" ||
           field == "latitude" || field == "longitude" || field == "utc_offset";
  });
}

bool check_wall(const Wall& w, std::size_t i, Report& report) {
  FieldChecker c(report, "wall", "walls", i, w.id);
  bool ok = c.check_fields(w);
  // Below its level's floor is where a wall of a level may start (docs/plan-format.md, "What
  // roomcad decides"); a wall without a level stands on z = 0 or above.
  if (w.level.empty() && std::isfinite(w.base) && w.base < 0)
    ok =
        c.fail("base", fmt::format("{}", w.base), "a number of at least 0 (a wall without a level)",
               fmt::format("set base of wall '{}' to 0 or more, or put the wall on a level", w.id));
  const bool ends = std::isfinite(w.from.x) && std::isfinite(w.from.y) && std::isfinite(w.to.x) &&
                    std::isfinite(w.to.y);
  if (ends && w.from == w.to)
    return c.fail("its length", "0 (from equals to)", "positive",
                  fmt::format("move `to` of wall '{}' away from `from`, or delete the wall", w.id));
  return ok;
}

void check_camera(const Camera& cam, std::size_t i, Report& report) {
  FieldChecker c(report, "camera", "cameras", i, cam.id);
  const bool ok = c.check_fields(cam);
  if (ok && cam.eye == cam.target) c.fail("target", "equal to eye", "a point other than the eye");
  const bool fov_ok = std::isfinite(cam.fov_deg) && cam.fov_deg > 0 && cam.fov_deg < 180;
  if (cam.projection == Projection::perspective && !fov_ok)
    c.fail("fov_deg", fmt::format("{}", cam.fov_deg), "between 0 and 180 degrees (e.g. 50)");
  else if (cam.projection == Projection::orthographic &&
           !(std::isfinite(cam.view_height) && cam.view_height > 0))
    c.fail("view_height", fmt::format("{}", cam.view_height), "a positive number (e.g. 10)");
}

/// invalid_value for a slab whose outline or holes are not simple, or whose holes are not
/// strictly inside the outline and apart (docs/plan-format.md, "slabs[]"). @return good.
bool check_slab_polygons(const Slab& slab, std::size_t i, Report& report) {
  FieldChecker c(report, "slab", "slabs", i, slab.id);
  if (!is_simple_polygon(slab.outline))
    return c.fail("outline", "a polygon whose edges cross or touch", "a simple polygon",
                  fmt::format("redraw the outline of slab '{}' so that its edges meet only at "
                              "their shared corners",
                              slab.id));
  for (std::size_t h = 0; h < slab.holes.size(); ++h) {
    const std::string field = fmt::format("holes[{}]", h);
    if (!is_simple_polygon(slab.holes[h]))
      return c.fail(field, "a polygon whose edges cross or touch", "a simple polygon");
    if (!is_strictly_inside(slab.holes[h], slab.outline))
      return c.fail(field, "not strictly inside the outline", "strictly inside the outline",
                    fmt::format("move or shrink hole {} of slab '{}' inside its outline, off "
                                "its edges",
                                h, slab.id));
    for (std::size_t k = 0; k < h; ++k)
      if (!are_disjoint(slab.holes[h], slab.holes[k]))
        return c.fail(field, fmt::format("meeting holes[{}]", k), "apart from the other holes",
                      fmt::format("merge holes {} and {} of slab '{}' into one", k, h, slab.id));
  }
  return true;
}

/// invalid_value for an obstruction whose outline is not simple. @return good.
bool check_obstruction_outline(const Obstruction& o, std::size_t i, Report& report) {
  return is_simple_polygon(o.outline) ||
         FieldChecker(report, "obstruction", "obstructions", i, o.id)
             .fail("outline", "a polygon whose edges cross or touch", "a simple polygon",
                   fmt::format("redraw the outline of obstruction '{}' so that its edges meet "
                               "only at their shared corners",
                               o.id));
}

/// invalid_value for an opening's shape that is not a simple polygon in the unit square.
bool check_shape(const Opening& o, std::size_t i, Report& report) {
  if (o.shape.empty()) return true;
  FieldChecker c(report, to_string(o.type), "openings", i, o.id);
  for (const Point2& p : o.shape)
    if (!(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1))
      return c.fail("shape", fmt::format("a polygon with the corner [{}, {}]", p.x, p.y),
                    "a polygon in the unit square [0, 1] x [0, 1]");
  return is_simple_polygon(o.shape) ||
         c.fail("shape", "a polygon whose edges cross or touch", "a simple polygon",
                fmt::format("redraw the shape of '{}' so that its edges meet only at their "
                            "shared corners",
                            o.id));
}

/// Checks each object of a list by its table. @return which were good.
template <class Object>
std::vector<bool> check_list(const std::vector<Object>& objects, std::string_view kind,
                             std::string_view list, Report& report) {
  std::vector<bool> good(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i)
    good[i] = FieldChecker(report, kind, list, i, objects[i].id).check_fields(objects[i]);
  return good;
}

}  // namespace

Usable check_values(const Plan& plan, Report& report) {
  Usable usable;
  usable.site = check_site(plan.site, report);
  (void)check_list(plan.levels, "level", "levels", report);
  usable.walls.resize(plan.walls.size());
  for (std::size_t i = 0; i < plan.walls.size(); ++i)
    usable.walls[i] = check_wall(plan.walls[i], i, report);
  usable.host.assign(plan.openings.size(), std::nullopt);
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    const Opening& o = plan.openings[i];
    if (FieldChecker(report, to_string(o.type), "openings", i, o.id).check_fields(o) &&
        check_shape(o, i, report))
      usable.host[i] = 0;  // the host is set by check_ids
  }
  usable.slabs = check_list(plan.slabs, "slab", "slabs", report);
  for (std::size_t i = 0; i < plan.slabs.size(); ++i)
    if (usable.slabs[i]) usable.slabs[i] = check_slab_polygons(plan.slabs[i], i, report);
  usable.obstructions = check_list(plan.obstructions, "obstruction", "obstructions", report);
  for (std::size_t i = 0; i < plan.obstructions.size(); ++i)
    if (usable.obstructions[i])
      usable.obstructions[i] = check_obstruction_outline(plan.obstructions[i], i, report);
  (void)check_list(plan.rooms, "room", "rooms", report);
  (void)check_list(plan.lights, "light", "lights", report);
  for (std::size_t i = 0; i < plan.cameras.size(); ++i) check_camera(plan.cameras[i], i, report);
  return usable;
}

}  // namespace roomcad::detail
