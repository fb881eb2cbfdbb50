// invalid_value: numbers that are not finite, sizes that are not positive, degenerate
// directions. A Plan built in code can hold anything, so nothing here is assumed.
#include <cmath>

#include <fmt/format.h>

#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"

namespace roomcad::detail {
namespace {

/// Checks the fields of one object, reporting each bad one; `ok()` is false after any.
class FieldChecker {
 public:
  FieldChecker(Report& report, std::string label, std::string id)
      : report_(report), label_(std::move(label)), id_(std::move(id)) {}

  bool finite(std::string_view field, double v) {
    return expect(std::isfinite(v), field, fmt::format("{}", v), "a finite number");
  }
  bool positive(std::string_view field, double v, double example) {
    return expect(std::isfinite(v) && v > 0, field, fmt::format("{}", v),
                  fmt::format("a positive number (e.g. {})", example));
  }
  bool non_negative(std::string_view field, double v) {
    return expect(std::isfinite(v) && v >= 0, field, fmt::format("{}", v),
                  "a number of at least 0");
  }
  bool finite(std::string_view field, Point2 p) {
    return expect(std::isfinite(p.x) && std::isfinite(p.y), field,
                  fmt::format("[{}, {}]", p.x, p.y), "two finite numbers");
  }
  bool finite(std::string_view field, Vec3 v) {
    return expect(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z), field,
                  fmt::format("[{}, {}, {}]", v.x, v.y, v.z), "three finite numbers");
  }
  bool non_zero(std::string_view field, Vec3 v) {
    return expect(v.x != 0 || v.y != 0 || v.z != 0, field, "[0, 0, 0]", "a non-zero direction");
  }
  /// Unless `good`, reports that `field` is `value` and must be `must_be`, with `fix` (or
  /// "set <field> to <must_be>").
  bool expect(bool good, std::string_view field, std::string_view value,
              std::string_view must_be, std::string fix = {}) {
    if (good) return true;
    ok_ = false;
    if (fix.empty()) fix = fmt::format("set {} of {} to {}", field, label_, must_be);
    report_.add(make_diagnostic(
        Severity::error, "invalid_value", id_.empty() ? std::vector<std::string>{}
                                                      : std::vector<std::string>{id_},
        fmt::format("{}: {} is {}; it must be {}.", label_, field, value, must_be),
        std::move(fix)));
    return false;
  }
  [[nodiscard]] bool ok() const { return ok_; }

 private:
  Report& report_;
  std::string label_;
  std::string id_;
  bool ok_ = true;
};

std::string label(std::string_view kind, std::string_view list, std::size_t i,
                  const std::string& id) {
  return fmt::format("{} '{}' ({}[{}])", kind, id, list, i);
}

void check_id(FieldChecker& c, const std::string& id) {
  c.expect(!id.empty(), "id", "empty", "a non-empty string unique in the plan");
}

bool check_site(const Site& s, Report& report) {
  FieldChecker c(report, "site", "");
  c.finite("origin", s.origin);
  for (int i = 0; i < 2; ++i)
    c.expect(s.cells[i] > 0, fmt::format("cells[{}]", i), fmt::format("{}", s.cells[i]),
             "a positive whole number of tiles");
  c.positive("cell_size", s.cell_size, 1.0);
  c.positive("max_height", s.max_height, 6.0);
  const bool bounds_ok = c.ok();
  c.positive("tolerance", s.tolerance, 1e-6);  // joins fall back to 0: the bounds still hold
  return bounds_ok;
}

bool check_wall(const Wall& w, std::size_t i, Report& report) {
  FieldChecker c(report, label("wall", "walls", i, w.id), w.id);
  check_id(c, w.id);
  const bool ends = c.finite("from", w.from) & c.finite("to", w.to);
  if (ends)
    c.expect(w.from != w.to, "its length", "0 (from equals to)", "positive",
             fmt::format("move `to` of {} away from `from`, or delete the wall", w.id));
  c.positive("thickness", w.thickness, 0.25);
  c.positive("height", w.height, 2.8);
  c.non_negative("base", w.base);
  return c.ok();
}

bool check_opening(const Opening& o, std::size_t i, Report& report) {
  const OpeningDefaults d = opening_defaults(o.type);
  FieldChecker c(report, label(to_string(o.type), "openings", i, o.id), o.id);
  check_id(c, o.id);
  c.finite("offset", o.offset);
  c.positive("width", o.width, d.width);
  c.positive("height", o.height, d.height);
  c.non_negative("sill", o.sill);
  return c.ok();
}

void check_light(const Light& l, std::size_t i, Report& report) {
  FieldChecker c(report, label("light", "lights", i, l.id), l.id);
  check_id(c, l.id);
  if (c.finite("direction", l.direction)) c.non_zero("direction", l.direction);
  c.finite("intensity", l.intensity);
  c.expect(std::isfinite(l.ambient) && l.ambient >= 0 && l.ambient <= 1, "ambient",
           fmt::format("{}", l.ambient), "in [0, 1]");
}

void check_camera(const Camera& cam, std::size_t i, Report& report) {
  FieldChecker c(report, label("camera", "cameras", i, cam.id), cam.id);
  check_id(c, cam.id);
  if (c.finite("eye", cam.eye) & c.finite("target", cam.target))
    c.expect(cam.eye != cam.target, "target", "equal to eye", "a point other than the eye");
  if (c.finite("up", cam.up)) c.non_zero("up", cam.up);
  if (cam.projection == Projection::perspective)
    c.expect(std::isfinite(cam.fov_deg) && cam.fov_deg > 0 && cam.fov_deg < 180, "fov_deg",
             fmt::format("{}", cam.fov_deg), "between 0 and 180 degrees (e.g. 50)");
  else
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
