// invalid_value: numbers that are not finite, sizes that are not positive, degenerate
// directions. A Plan built in code can hold anything, so nothing here is assumed.
#include <cmath>

#include <fmt/format.h>

#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"

namespace roomcad::detail {
namespace {

/// Checks the fields of one object, reporting each bad one; `ok()` is false after any.
/// Texts are only formatted for a bad field: checking 100,000 good walls formats nothing.
class FieldChecker {
 public:
  /// `list` and `index` locate the object ("walls", 3); an empty list means the site.
  FieldChecker(Report& report, std::string_view kind, std::string_view list, std::size_t index,
               std::string_view id)
      : report_(report), kind_(kind), list_(list), index_(index), id_(id) {}

  bool finite(std::string_view field, double v) {
    return std::isfinite(v) || fail(field, fmt::format("{}", v), "a finite number");
  }
  bool positive(std::string_view field, double v, double example) {
    return (std::isfinite(v) && v > 0) ||
           fail(field, fmt::format("{}", v), fmt::format("a positive number (e.g. {})", example));
  }
  bool non_negative(std::string_view field, double v) {
    return (std::isfinite(v) && v >= 0) ||
           fail(field, fmt::format("{}", v), "a number of at least 0");
  }
  bool finite(std::string_view field, Point2 p) {
    return (std::isfinite(p.x) && std::isfinite(p.y)) ||
           fail(field, fmt::format("[{}, {}]", p.x, p.y), "two finite numbers");
  }
  bool finite(std::string_view field, Vec3 v) {
    return (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) ||
           fail(field, fmt::format("[{}, {}, {}]", v.x, v.y, v.z), "three finite numbers");
  }
  /// Lengths and coordinates must also lie in the range exact geometry is computed in:
  /// 0, or a magnitude from 1e-15 m (below a femtometre) to 1e15 m (beyond the solar system).
  /// Outside it the exact number types lose their footing (and no plan needs it).
  bool computable(std::string_view field, double v) {
    const double m = std::fabs(v);
    return m == 0 || (m >= 1e-15 && m <= 1e15) ||
           fail(field, fmt::format("{}", v), "0 or between 1e-15 and 1e15 m in size");
  }
  bool computable(std::string_view field, Point2 p) {
    return (computable(field, p.x) && computable(field, p.y));
  }
  bool non_zero(std::string_view field, Vec3 v) {
    return v.x != 0 || v.y != 0 || v.z != 0 || fail(field, "[0, 0, 0]", "a non-zero direction");
  }
  /// Reports that `field` is `value` and must be `must_be`, with `fix` (or "set <field> to
  /// <must_be>"). @return false, for `good || fail(...)`.
  bool fail(std::string_view field, std::string_view value, std::string_view must_be,
            std::string fix = {}) {
    ok_ = false;
    const std::string label =
        list_.empty() ? std::string(kind_)
                      : fmt::format("{} '{}' ({}[{}])", kind_, id_, list_, index_);
    if (fix.empty()) fix = fmt::format("set {} of {} to {}", field, label, must_be);
    report_.add(make_diagnostic(
        Severity::error, Code::invalid_value,
        id_.empty() ? std::vector<std::string>{} : std::vector<std::string>{std::string(id_)},
        fmt::format("{}: {} is {}; it must be {}.", label, field, value, must_be),
        std::move(fix)));
    return false;
  }
  [[nodiscard]] bool ok() const { return ok_; }

 private:
  Report& report_;
  std::string_view kind_;
  std::string_view list_;
  std::size_t index_;
  std::string_view id_;
  bool ok_ = true;
};

void check_id(FieldChecker& c, const std::string& id) {
  if (id.empty()) c.fail("id", "empty", "a non-empty string unique in the plan");
}

bool check_site(const Site& s, Report& report) {
  FieldChecker c(report, "site", "", 0, "");
  if (c.finite("origin", s.origin)) c.computable("origin", s.origin);
  for (int i = 0; i < 2; ++i)
    if (s.cells[i] <= 0)
      c.fail(fmt::format("cells[{}]", i), fmt::format("{}", s.cells[i]),
             "a positive whole number of tiles");
  if (c.positive("cell_size", s.cell_size, 1.0)) c.computable("cell_size", s.cell_size);
  if (c.positive("max_height", s.max_height, 6.0)) c.computable("max_height", s.max_height);
  const bool bounds_ok = c.ok();
  // Joins fall back to a tolerance of 0 when it is bad: the bounds still hold.
  if (c.positive("tolerance", s.tolerance, 1e-6)) c.computable("tolerance", s.tolerance);
  return bounds_ok;
}

bool check_wall(const Wall& w, std::size_t i, Report& report) {
  FieldChecker c(report, "wall", "walls", i, w.id);
  check_id(c, w.id);
  // Both ends checked (and reported) before either verdict is used: no short circuit.
  const bool from_ok = c.finite("from", w.from) && c.computable("from", w.from);
  const bool to_ok = c.finite("to", w.to) && c.computable("to", w.to);
  const bool ends = from_ok && to_ok;
  if (ends && w.from == w.to)
    c.fail("its length", "0 (from equals to)", "positive",
           fmt::format("move `to` of wall '{}' away from `from`, or delete the wall", w.id));
  if (c.positive("thickness", w.thickness, 0.25)) c.computable("thickness", w.thickness);
  if (c.positive("height", w.height, 2.8)) c.computable("height", w.height);
  if (c.non_negative("base", w.base)) c.computable("base", w.base);
  return c.ok();
}

bool check_opening(const Opening& o, std::size_t i, Report& report) {
  const OpeningDefaults d = opening_defaults(o.type);
  FieldChecker c(report, to_string(o.type), "openings", i, o.id);
  check_id(c, o.id);
  if (c.finite("offset", o.offset)) c.computable("offset", o.offset);
  if (c.positive("width", o.width, d.width)) c.computable("width", o.width);
  if (c.positive("height", o.height, d.height)) c.computable("height", o.height);
  if (c.non_negative("sill", o.sill)) c.computable("sill", o.sill);
  return c.ok();
}

void check_light(const Light& l, std::size_t i, Report& report) {
  FieldChecker c(report, "light", "lights", i, l.id);
  check_id(c, l.id);
  if (c.finite("direction", l.direction)) c.non_zero("direction", l.direction);
  c.finite("intensity", l.intensity);
  if (!(std::isfinite(l.ambient) && l.ambient >= 0 && l.ambient <= 1))
    c.fail("ambient", fmt::format("{}", l.ambient), "in [0, 1]");
}

void check_camera(const Camera& cam, std::size_t i, Report& report) {
  FieldChecker c(report, "camera", "cameras", i, cam.id);
  check_id(c, cam.id);
  const bool eye_ok = c.finite("eye", cam.eye);  // both reported: no short circuit
  const bool target_ok = c.finite("target", cam.target);
  if (eye_ok && target_ok && cam.eye == cam.target)
    c.fail("target", "equal to eye", "a point other than the eye");
  if (c.finite("up", cam.up)) c.non_zero("up", cam.up);
  const bool fov_ok = std::isfinite(cam.fov_deg) && cam.fov_deg > 0 && cam.fov_deg < 180;
  if (cam.projection == Projection::perspective && !fov_ok)
    c.fail("fov_deg", fmt::format("{}", cam.fov_deg), "between 0 and 180 degrees (e.g. 50)");
  else if (cam.projection == Projection::orthographic)
    c.positive("view_height", cam.view_height, 10.0);
}

}  // namespace

Usable check_values(const Plan& plan, Report& report) {
  Usable usable;
  usable.site = check_site(plan.site, report);
  usable.walls.resize(plan.walls.size());
  for (std::size_t i = 0; i < plan.walls.size(); ++i)
    usable.walls[i] = check_wall(plan.walls[i], i, report);
  usable.host.assign(plan.openings.size(), std::nullopt);
  for (std::size_t i = 0; i < plan.openings.size(); ++i)
    if (check_opening(plan.openings[i], i, report)) usable.host[i] = 0;  // host set by check_ids
  for (std::size_t i = 0; i < plan.lights.size(); ++i) check_light(plan.lights[i], i, report);
  for (std::size_t i = 0; i < plan.cameras.size(); ++i) check_camera(plan.cameras[i], i, report);
  return usable;
}

}  // namespace roomcad::detail
