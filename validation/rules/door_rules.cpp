// SPDX-License-Identifier: GPL-3.0-or-later
// door_swing_blocked, door_clearance and door_too_narrow.
//
// A leaf is blocked when its swept quarter disc shares interior area with a wall (other than
// its own: the disc lies beyond that wall's face) or with another door's swept disc, where
// their heights overlap; touching is not hitting. The clear rectangle in front of a door
// (push side) must share no interior area with a wall people walk into. Both are exact on
// the written numbers (written_number.h). The width rule and the clear rectangle apply to
// the doors of accessible rooms (every room unless a rules file names them).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/detail/diagnostics.h"
#include "validation/rules/door_fixes.h"
#include "validation/rules/door_geometry.h"
#include "validation/rules/door_tests.h"
#include "validation/rules/rules.h"

namespace roomcad::rules {
namespace {

std::vector<std::string> ids_of(const Plan& plan, std::size_t door,
                                const std::vector<std::size_t>& walls) {
  std::vector<std::string> ids{plan.openings[door].id};
  for (const std::size_t w : walls) ids.push_back(plan.walls[w].id);
  return ids;
}

std::string quoted_list(const Plan& plan, const std::vector<std::size_t>& walls) {
  std::vector<std::string> names;
  for (const std::size_t w : walls) names.push_back(fmt::format("'{}'", plan.walls[w].id));
  return fmt::format("{} {}", walls.size() == 1 ? "wall" : "walls", fmt::join(names, ", "));
}

Where polygon_where(const Poly<double>& p) {
  double lx = p[0].x, hx = lx, ly = p[0].y, hy = ly;
  for (std::size_t i = 1; i < p.n; ++i) {
    lx = std::min(lx, p[i].x), hx = std::max(hx, p[i].x);
    ly = std::min(ly, p[i].y), hy = std::max(hy, p[i].y);
  }
  return detail::box_where(lx, ly, hx, hy);
}

std::string leaf_words(const Opening& o) {
  return fmt::format("hinge {}, swing {}, {} wide", to_string(o.hinge), to_string(o.swing),
                     detail::metres(o.width));
}

/// The fix's words and edits, or what to do when no tried change clears it.
std::pair<std::string, std::vector<FixEdit>> fix_or(const std::optional<DoorFix>& fix,
                                                    std::string otherwise) {
  if (!fix) return {std::move(otherwise), {}};
  return {fix->text, fix->edits};
}

struct DoorChecks {
  const Context& cx;
  const Scene& scene;
  const DoorFixer& fixer;
  Report& report;

  void leaf_against_walls(std::size_t i, std::size_t host) const {
    const Plan& plan = scene.plan();
    const Opening& o = plan.openings[i];
    const std::vector<std::size_t> hit = walls_hit_by_leaf(scene, o, host);
    if (hit.empty()) return;
    auto [fix, edits] =
        fix_or(fixer.find(i, Code::door_swing_blocked),
               fmt::format("no hinge side, swing or place along wall '{}' clears it: use a "
                           "narrower or a sliding door, or move {}",
                           plan.walls[host].id, quoted_list(plan, hit)));
    report.add(make_finding(
        cx, Code::door_swing_blocked, ids_of(plan, i, hit),
        fmt::format("door '{}' cannot open fully: its leaf ({}) sweeps through {}.", o.id,
                    leaf_words(o), quoted_list(plan, hit)),
        std::move(fix), std::move(edits),
        polygon_where(leaf_sweep<double>(plan.walls[host], o, o.hinge, o.swing).square)));
  }

  void leaf_against_leaves(std::size_t i, std::size_t host,
                           const std::vector<std::size_t>& others) const {
    const Plan& plan = scene.plan();
    const Opening& a = plan.openings[i];
    for (const std::size_t j : others) {
      const Opening& b = plan.openings[j];
      if (j <= i || !leaves_meet(scene, a, host, b, *scene.host(j))) continue;
      std::optional<DoorFix> fix = fixer.find(i, Code::door_swing_blocked);
      if (!fix) fix = fixer.find(j, Code::door_swing_blocked);
      if (fix) fix->text = fmt::format("door '{}': {}", fix->edits.front().id, fix->text);
      auto [text, edits] =
          fix_or(fix,
                 "no hinge side, swing or place along their walls clears them: use a "
                 "sliding door for one of them");
      const Poly<double> sa = leaf_sweep<double>(plan.walls[host], a, a.hinge, a.swing).square;
      report.add(make_finding(
          cx, Code::door_swing_blocked, {a.id, b.id},
          fmt::format("the leaves of door '{}' ({}) and door '{}' ({}) sweep into each other.",
                      a.id, leaf_words(a), b.id, leaf_words(b)),
          std::move(text), std::move(edits), polygon_where(sa)));
    }
  }

  void clearance(std::size_t i, std::size_t host) const {
    const Plan& plan = scene.plan();
    const Opening& o = plan.openings[i];
    const RuleThresholds& t = cx.rules.thresholds;
    const std::vector<std::size_t> hit = walls_in_clearance(scene, o, host, t);
    if (hit.empty()) return;
    auto [fix, edits] =
        fix_or(fixer.find(i, Code::door_clearance),
               fmt::format("no swing or place along wall '{}' gives it the clear space: move {}",
                           plan.walls[host].id, quoted_list(plan, hit)));
    report.add(make_finding(
        cx, Code::door_clearance, ids_of(plan, i, hit),
        fmt::format("the clear space in front of door '{}' on its push side ({} x {} on its wall's "
                    "{} side) runs "
                    "into {}.",
                    o.id, detail::metres(t.clearance_width), detail::metres(t.clearance_depth),
                    o.swing == Swing::in ? "right" : "left", quoted_list(plan, hit)),
        std::move(fix), std::move(edits),
        polygon_where(clearance_rectangle<double>(plan.walls[host], o, o.swing, t.clearance_width,
                                                  t.clearance_depth))));
  }

  void width(std::size_t i, std::size_t host) const {
    const Plan& plan = scene.plan();
    const Opening& o = plan.openings[i];
    const double min = cx.rules.thresholds.door_min_width;
    if (!is_narrower(o.width, min)) return;
    auto [fix, edits] =
        fix_or(fixer.widen(i), fmt::format("wall '{}' has no room for it at {} wide: move it or "
                                           "lengthen the wall",
                                           plan.walls[host].id, detail::metres(min)));
    const WallFrame<double> f = wall_frame<double>(plan.walls[host]);
    const Pt<double> a = f.at(o.offset, -f.half), b = f.at(o.offset + o.width, f.half);
    report.add(make_finding(cx, Code::door_too_narrow, {o.id},
                            fmt::format("door '{}' is {} wide, narrower than {}.", o.id,
                                        detail::metres(o.width), detail::metres(min)),
                            std::move(fix), std::move(edits),
                            detail::box_where(std::min(a.x, b.x), std::min(a.y, b.y),
                                              std::max(a.x, b.x), std::max(a.y, b.y))));
  }
};

/// For each door, the other doors whose leaf boxes meet its own.
std::vector<std::vector<std::size_t>> neighbouring_leaves(const Scene& scene,
                                                          const std::vector<std::size_t>& doors) {
  std::vector<Box2> boxes;
  for (const std::size_t i : doors) {
    Box2 b = leaf_box(scene, scene.plan().openings[i], *scene.host(i));
    b.index = i;
    boxes.push_back(b);
  }
  std::vector<std::vector<std::size_t>> out(scene.plan().openings.size());
  for (const auto& [a, b] : find_meeting_boxes(boxes)) out[a].push_back(b);
  return out;
}

}  // namespace

void check_doors(const Context& cx, const Scene& scene, Report& report) {
  const RuleSet& rules = cx.rules;
  const bool swing = rules.is_enabled(Code::door_swing_blocked);
  const bool clear = rules.is_enabled(Code::door_clearance);
  const bool narrow = rules.is_enabled(Code::door_too_narrow);
  if (!swing && !clear && !narrow) return;
  std::vector<std::size_t> doors;
  for (std::size_t i = 0; i < scene.plan().openings.size(); ++i)
    if (scene.plan().openings[i].type == OpeningType::door && scene.host(i)) doors.push_back(i);
  const DoorFixer fixer(cx, scene);
  const DoorChecks checks{cx, scene, fixer, report};
  const std::vector<std::vector<std::size_t>> others =
      swing ? neighbouring_leaves(scene, doors) : std::vector<std::vector<std::size_t>>{};
  for (const std::size_t i : doors) {
    const std::size_t host = *scene.host(i);
    if (swing) checks.leaf_against_walls(i, host), checks.leaf_against_leaves(i, host, others[i]);
    if (clear && cx.accessible_door[i]) checks.clearance(i, host);
    if (narrow && cx.accessible_door[i]) checks.width(i, host);
  }
}

}  // namespace roomcad::rules
