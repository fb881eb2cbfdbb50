// SPDX-License-Identifier: GPL-3.0-or-later
// window_sill_low, window_sill_high and duplicate_object.
//
// Sills are compared with the thresholds in the written numbers. Two objects are duplicates
// when their geometry is the same numbers: walls with the same ends (either way round),
// thickness, height and base; openings of one wall with the same rectangle; lights with the
// same type and direction; cameras with the same view. The later one is the copy.
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "validation/detail/diagnostics.h"
#include "validation/rules/door_geometry.h"
#include "validation/rules/fix_search.h"
#include "validation/rules/rules.h"

namespace roomcad::rules {
namespace {

Where hole_where(const Wall& w, const Opening& o) {
  const WallFrame<double> f = wall_frame<double>(w);
  const Pt<double> a = f.at(o.offset, -f.half), b = f.at(o.offset + o.width, f.half);
  return detail::box_where(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x),
                           std::max(a.y, b.y));
}

bool is_below(double a, double b) {
  return decide_written([&](auto tag) {
    using NT = decltype(tag);
    return NT(a) < NT(b);
  });
}

/// A sill change, tried on the neighbourhood; the window's height shrinks if the top would
/// leave the wall.
std::pair<std::string, std::vector<FixEdit>> sill_fix(const Scene& scene, std::size_t i,
                                                      double sill) {
  const Opening& o = scene.plan().openings[i];
  const Wall& w = scene.plan().walls[*scene.host(i)];
  std::vector<std::pair<std::string, std::string>> fields{{"sill", number_text(sill)}};
  std::string text = fmt::format("set its sill to {} m", number_text(sill));
  if (sill + o.height > w.height) {
    const double height = centimetres_down(w.height - sill);
    if (height <= 0)
      return {fmt::format("wall '{}' is too low for a sill at {} m", w.id, number_text(sill)), {}};
    fields.emplace_back("height", number_text(height));
    text += fmt::format(" and its height to {} m", number_text(height));
  }
  std::vector<FixEdit> edits{set_edit(o.id, std::move(fields))};
  if (!Neighbourhood(scene, scene.wall_box(*scene.host(i)), heights_of(w)).try_edits(edits))
    return {text + " (this makes it meet another opening: move that one first)", {}};
  return {std::move(text), std::move(edits)};
}

void check_sill(const Context& cx, const Scene& scene, std::size_t i, Report& report) {
  const Opening& o = scene.plan().openings[i];
  const Wall& w = scene.plan().walls[*scene.host(i)];
  const RuleThresholds& t = cx.rules.thresholds;
  if (cx.rules.is_enabled(Code::window_sill_low) && is_below(o.sill, t.window_min_sill)) {
    auto [fix, edits] = sill_fix(scene, i, centimetres_up(t.window_min_sill));
    report.add(make_finding(
        cx, Code::window_sill_low, {o.id},
        fmt::format("window '{}' has its sill {} above the floor, below {}: a fall risk "
                    "without a guard.",
                    o.id, detail::metres(o.sill), detail::metres(t.window_min_sill)),
        fix + ", or add a guard rail", std::move(edits), hole_where(w, o)));
  }
  if (cx.rules.is_enabled(Code::window_sill_high) && is_below(t.window_max_sill, o.sill)) {
    auto [fix, edits] = sill_fix(scene, i, centimetres_down(t.window_max_sill));
    report.add(make_finding(
        cx, Code::window_sill_high, {o.id},
        fmt::format("window '{}' has its sill {} above the floor, above {}: no view out "
                    "from a seat and no way out through it.",
                    o.id, detail::metres(o.sill), detail::metres(t.window_max_sill)),
        std::move(fix), std::move(edits), hole_where(w, o)));
  }
}

/// Calls f(first, later) for every object whose key equals an earlier one's.
template <class Key, class F>
void for_each_copy(const std::vector<std::optional<Key>>& keys, F f) {
  std::map<Key, std::size_t> first;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!keys[i]) continue;
    const auto [it, fresh] = first.emplace(*keys[i], i);
    if (!fresh) f(it->second, i);
  }
}

using WallKey = std::tuple<double, double, double, double, double, double, double>;

std::optional<WallKey> wall_key(const Wall& w) {
  const auto lo = std::min(std::pair{w.from.x, w.from.y}, std::pair{w.to.x, w.to.y});
  const auto hi = std::max(std::pair{w.from.x, w.from.y}, std::pair{w.to.x, w.to.y});
  return WallKey{lo.first, lo.second, hi.first, hi.second, w.thickness, w.height, w.base};
}

/// Edits that move the copy's openings to the original (unless the original has them too)
/// and remove the copy.
std::vector<FixEdit> merge_walls(const Plan& plan, const Wall& keep, const Wall& copy) {
  std::vector<FixEdit> edits;
  const bool reversed = keep.from != copy.from;
  const double length = std::hypot(copy.to.x - copy.from.x, copy.to.y - copy.from.y);
  for (const Opening& o : plan.openings) {
    if (o.wall != copy.id) continue;
    const double offset = reversed ? length - o.offset - o.width : o.offset;
    const bool twin =
        std::any_of(plan.openings.begin(), plan.openings.end(), [&](const Opening& k) {
          return k.wall == keep.id && k.offset == offset && k.width == o.width &&
                 k.sill == o.sill && k.height == o.height;
        });
    if (!twin)
      edits.push_back(set_edit(o.id, {{"wall", keep.id}, {"offset", number_text(offset)}}));
  }
  FixEdit remove;
  remove.op = FixEdit::Op::remove;
  remove.id = copy.id;
  remove.cascade = true;
  edits.push_back(remove);
  return edits;
}

FixEdit remove_edit(const std::string& id) {
  FixEdit e;
  e.op = FixEdit::Op::remove;
  e.id = id;
  return e;
}

void report_copy(const Context& cx, std::string kind, const std::string& keep,
                 const std::string& copy, std::vector<FixEdit> edits, std::string fix,
                 std::optional<Where> where, Report& report) {
  report.add(
      make_finding(cx, Code::duplicate_object, {keep, copy},
                   fmt::format("{} '{}' is a copy of {} '{}': the same geometry, drawn twice.",
                               kind, copy, kind, keep),
                   std::move(fix), std::move(edits), std::move(where)));
}

void check_wall_copies(const Context& cx, const Scene& scene, Report& report) {
  const Plan& plan = scene.plan();
  std::vector<std::optional<WallKey>> keys(plan.walls.size());
  for (std::size_t w = 0; w < plan.walls.size(); ++w)
    if (scene.is_usable(w)) keys[w] = wall_key(plan.walls[w]);
  for_each_copy(keys, [&](std::size_t keep, std::size_t copy) {
    std::vector<FixEdit> edits = merge_walls(plan, plan.walls[keep], plan.walls[copy]);
    const std::string fix = fmt::format(
        "delete wall '{}'{}", plan.walls[copy].id,
        edits.size() > 1 ? fmt::format(", moving its openings to wall '{}'", plan.walls[keep].id)
                         : "");
    if (!Neighbourhood(scene, scene.wall_box(copy), heights_of(plan.walls[copy])).try_edits(edits))
      edits.clear();
    const Box2& b = scene.wall_box(copy);
    report_copy(cx, "wall", plan.walls[keep].id, plan.walls[copy].id, std::move(edits), fix,
                detail::box_where(b.min_x, b.min_y, b.max_x, b.max_y), report);
  });
}

void check_other_copies(const Context& cx, const Scene& scene, Report& report) {
  const Plan& plan = scene.plan();
  using OpeningKey = std::tuple<std::size_t, double, double, double, double>;
  std::vector<std::optional<OpeningKey>> openings(plan.openings.size());
  for (std::size_t i = 0; i < plan.openings.size(); ++i)
    if (const Opening& o = plan.openings[i]; scene.host(i))
      openings[i] = OpeningKey{*scene.host(i), o.offset, o.width, o.height, o.sill};
  for_each_copy(openings, [&](std::size_t keep, std::size_t copy) {
    const Opening& c = plan.openings[copy];
    report_copy(cx, std::string(to_string(c.type)), plan.openings[keep].id, c.id,
                {remove_edit(c.id)}, fmt::format("delete {} '{}'", to_string(c.type), c.id),
                hole_where(plan.walls[*scene.host(copy)], c), report);
  });
  using LightKey = std::tuple<int, double, double, double>;
  std::vector<std::optional<LightKey>> lights;
  for (const Light& l : plan.lights)
    lights.emplace_back(
        LightKey{static_cast<int>(l.type), l.direction.x, l.direction.y, l.direction.z});
  for_each_copy(lights, [&](std::size_t keep, std::size_t copy) {
    report_copy(cx, "light", plan.lights[keep].id, plan.lights[copy].id,
                {remove_edit(plan.lights[copy].id)},
                fmt::format("delete light '{}' (a copy doubles the light)", plan.lights[copy].id),
                std::nullopt, report);
  });
  using CameraKey = std::tuple<int, double, double, double, double, double, double, double, double,
                               double, double>;
  std::vector<std::optional<CameraKey>> cameras;
  for (const Camera& c : plan.cameras)
    cameras.emplace_back(
        CameraKey{static_cast<int>(c.projection), c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y,
                  c.target.z, c.up.x, c.up.y, c.up.z,
                  c.projection == Projection::perspective ? c.fov_deg : c.view_height});
  for_each_copy(cameras, [&](std::size_t keep, std::size_t copy) {
    const Camera& c = plan.cameras[copy];
    report_copy(cx, "camera", plan.cameras[keep].id, c.id, {remove_edit(c.id)},
                fmt::format("delete camera '{}'", c.id), Where{{c.eye.x, c.eye.y}, std::nullopt},
                report);
  });
}

}  // namespace

void check_windows(const Context& cx, const Scene& scene, Report& report) {
  if (!cx.rules.is_enabled(Code::window_sill_low) && !cx.rules.is_enabled(Code::window_sill_high))
    return;
  for (std::size_t i = 0; i < scene.plan().openings.size(); ++i)
    if (scene.plan().openings[i].type == OpeningType::window && scene.host(i))
      check_sill(cx, scene, i, report);
}

void check_duplicates(const Context& cx, const Scene& scene, Report& report) {
  if (!cx.rules.is_enabled(Code::duplicate_object)) return;
  check_wall_copies(cx, scene, report);
  check_other_copies(cx, scene, report);
}

}  // namespace roomcad::rules
