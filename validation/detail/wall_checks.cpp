// SPDX-License-Identifier: GPL-3.0-or-later
// wall_overlap and out_of_bounds, on the walls that passed the value checks.
//
// Walls are their mitred footprints times [base, base + height]. Two walls that are not
// joined overlap when those solids share interior volume; joined walls are excused unless
// their centre lines overlap along a positive length (then they are one wall drawn twice).
// Every verdict is exact (exact::decide); distances in messages are doubles.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>

#include <fmt/format.h>

#include "geometry/segment_predicates.h"
#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"
#include "validation/detail/resolved_plan.h"
#include "validation/detail/shapes.h"

namespace roomcad::detail {
namespace {

/// The part of b's centre line along a's (both on one line), in doubles, for the message.
std::pair<Point2, Point2> shared_run(const Wall& a, const Wall& b) {
  const double dx = a.to.x - a.from.x, dy = a.to.y - a.from.y;
  const auto along = [&](Point2 p) { return (p.x - a.from.x) * dx + (p.y - a.from.y) * dy; };
  const double len2 = dx * dx + dy * dy;
  const double lo = std::max({0.0, std::min(along(b.from), along(b.to))});
  const double hi = std::min({len2, std::max(along(b.from), along(b.to))});
  const auto at = [&](double t) {
    return Point2{a.from.x + t / len2 * dx, a.from.y + t / len2 * dy};
  };
  return {at(lo), at(hi)};
}

void report_shared_centre_line(const Wall& a, const Wall& b, Report& report) {
  const auto [p, q] = shared_run(a, b);
  report.add(make_diagnostic(
      Severity::error, Code::wall_overlap, {a.id, b.id},
      fmt::format("{} and {} run along the same centre line for {}, from {} to {}.", name_of(a),
                  name_of(b), metres(std::hypot(q.x - p.x, q.y - p.y)), point_text(p),
                  point_text(q)),
      fmt::format("shorten {} so that it only meets {} at an end, or delete it if it is a "
                  "duplicate",
                  b.id, a.id),
      box_where(std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x), std::max(p.y, q.y))));
}

void report_overlap(const Wall& a, const Wall& b, const std::array<Point2, 4>& fa,
                    const std::array<Point2, 4>& fb, const Box2& box, Report& report) {
  const auto [depth, dir] = penetration(fa, fb);
  report.add(make_diagnostic(
      Severity::error, Code::wall_overlap, {a.id, b.id},
      fmt::format("{} and {} overlap by {} but are not joined (their centre lines do not meet).",
                  name_of(a), name_of(b), metres(depth)),
      fmt::format("move {} {} {} (or thin one of them), or extend one centre line to meet the "
                  "other so that they join",
                  b.id, metres_at_least(depth), direction_text(dir)),
      box_where(box.min_x, box.min_y, box.max_x, box.max_y)));
}

bool solids_overlap(const Plan& plan, const Footprints& fp, std::size_t a, std::size_t b) {
  const Wall& wa = plan.walls[a];
  const Wall& wb = plan.walls[b];
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    if (!spans_overlap(NT(wa.base), NT(wa.base) + NT(highest_height(wa)), NT(wb.base),
                       NT(wb.base) + NT(highest_height(wb))))
      return false;
    return interiors_overlap(fp.get<NT>(a), fp.get<NT>(b));
  });
}

Box2 common_box(const Box2& p, const Box2& q) {
  return {std::max(p.min_x, q.min_x), std::max(p.min_y, q.min_y), std::min(p.max_x, q.max_x),
          std::min(p.max_y, q.max_y), 0};
}

void check_overlaps(const ResolvedPlan& r, const Joins& joins, const Footprints& fp,
                    Report& report) {
  const Plan& plan = r.plan;
  std::vector<const Box2*> box_of_wall(plan.walls.size(), nullptr);
  for (const Box2& b : fp.boxes()) box_of_wall[b.index] = &b;
  std::set<std::pair<std::size_t, std::size_t>> reported;  // by input wall: arcs once
  for (const auto& [a, b] : find_meeting_boxes(fp.boxes())) {
    const std::pair<std::size_t, std::size_t> walls =
        std::minmax(r.source_wall[a], r.source_wall[b]);
    if (walls.first == walls.second || reported.contains(walls)) continue;  // one arc's chords
    const Wall& wa = plan.walls[a];
    const Wall& wb = plan.walls[b];
    if (joins.are_joined(a, b)) {
      if (overlap_collinearly(wa.from, wa.to, wb.from, wb.to)) {
        reported.insert(walls);
        report_shared_centre_line(wa, wb, report);
      }
      continue;
    }
    if (!solids_overlap(plan, fp, a, b)) continue;
    reported.insert(walls);
    report_overlap(wa, wb, approximate_footprint(plan, joins, a),
                   approximate_footprint(plan, joins, b),
                   common_box(*box_of_wall[a], *box_of_wall[b]), report);
  }
}

struct SiteRect {
  double x0, y0, x1, y1;  ///< rounded; the verdicts use the exact sums
};

SiteRect site_rect(const Site& s) {
  return {s.origin.x, s.origin.y, s.origin.x + static_cast<double>(s.cells[0]) * s.cell_size,
          s.origin.y + static_cast<double>(s.cells[1]) * s.cell_size};
}

bool is_inside_site(const Site& s, const Footprints& fp, std::size_t w) {
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    const NT x0(s.origin.x), y0(s.origin.y);
    const NT x1 = x0 + NT(static_cast<double>(s.cells[0])) * NT(s.cell_size);
    const NT y1 = y0 + NT(static_cast<double>(s.cells[1])) * NT(s.cell_size);
    for (const auto& c : fp.get<NT>(w))  // the footprint is convex: its corners decide
      if (c.x < x0 || c.x > x1 || c.y < y0 || c.y > y1) return false;
    return true;
  });
}

/// @return "cells [7, 6]" (and " from origin [x, y]" if it must move): the smallest site on
/// the same tile grid that holds both the old site and the box; nothing if that takes more
/// than 2^53 cells a side (no plan can state such a count exactly).
std::optional<std::string> enlarged_site(const SiteRect& r, double cs, double lo_x, double lo_y,
                                         double hi_x, double hi_y) {
  const auto grown_origin = [cs](double o, double lo) {
    return lo < o ? o - std::ceil((o - lo) / cs) * cs : o;
  };
  const double ox = grown_origin(r.x0, lo_x), oy = grown_origin(r.y0, lo_y);
  const auto cells = [cs](double o, double hi, double site_hi) {
    return std::ceil((std::max(hi, site_hi) - o) / cs);
  };
  const double nx = cells(ox, hi_x, r.x1), ny = cells(oy, hi_y, r.y1);
  constexpr double kMostCells = 9007199254740992.0;  // 2^53
  if (!(nx <= kMostCells && ny <= kMostCells)) return std::nullopt;
  std::string text =
      fmt::format("cells [{}, {}]", static_cast<std::int64_t>(nx), static_cast<std::int64_t>(ny));
  if (ox != r.x0 || oy != r.y0) text += fmt::format(" from origin [{}, {}]", ox, oy);
  return text;
}

std::string fix_outside_site(const std::string& distance, const char* direction,
                             const std::optional<std::string>& site) {
  if (!site) return fmt::format("move it {} {}", distance, direction);
  return fmt::format("move it {} {}, or enlarge the site to {}", distance, direction, *site);
}

void report_outside_site(const Plan& plan, const std::array<Point2, 4>& f, const Wall& w,
                         Report& report) {
  const SiteRect r = site_rect(plan.site);
  double lo_x = f[0].x, lo_y = f[0].y, hi_x = lo_x, hi_y = lo_y;
  for (const Point2& c : f) {
    lo_x = std::min(lo_x, c.x), hi_x = std::max(hi_x, c.x);
    lo_y = std::min(lo_y, c.y), hi_y = std::max(hi_y, c.y);
  }
  struct Side {
    double excess;
    const char* edge;
    const char* back;
  };
  const Side sides[4] = {{r.x0 - lo_x, "west", "east"},
                         {hi_x - r.x1, "east", "west"},
                         {r.y0 - lo_y, "south", "north"},
                         {hi_y - r.y1, "north", "south"}};
  const Side& worst = *std::max_element(
      sides, sides + 4, [](const Side& a, const Side& b) { return a.excess < b.excess; });
  report.add(make_diagnostic(
      Severity::error, Code::out_of_bounds, {w.id},
      fmt::format("{} reaches {} past the {} edge of the site [{}, {}] x [{}, {}].", name_of(w),
                  metres(std::max(worst.excess, 0.0)), worst.edge, r.x0, r.x1, r.y0, r.y1),
      fix_outside_site(metres_at_least(std::max(worst.excess, 0.0)), worst.back,
                       enlarged_site(r, plan.site.cell_size, lo_x, lo_y, hi_x, hi_y)),
      box_where(lo_x, lo_y, hi_x, hi_y)));
}

bool is_under_max_height(const Site& s, const Wall& w) {
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    return NT(w.base) + NT(highest_height(w)) <= NT(s.max_height);
  });
}

void report_too_high(const Site& s, const Wall& w, const std::array<Point2, 4>& f, Report& report) {
  const double height = highest_height(w);
  report.add(make_diagnostic(
      Severity::error, Code::out_of_bounds, {w.id},
      fmt::format("{} rises to {} (base {} + height {}), above the site's max_height {}.",
                  name_of(w), metres(w.base + height), metres(w.base), metres(height),
                  metres(s.max_height)),
      w.base < s.max_height
          ? fmt::format("lower its height to {} or less, or raise site.max_height",
                        metres_at_most(s.max_height - w.base))
          : fmt::format("its base is at or above the site's max_height: lower its base below {}, "
                        "or raise site.max_height to at least {}",
                        metres(s.max_height), metres_at_least(w.base + height)),
      box_where(
          std::min({f[0].x, f[1].x, f[2].x, f[3].x}), std::min({f[0].y, f[1].y, f[2].y, f[3].y}),
          std::max({f[0].x, f[1].x, f[2].x, f[3].x}), std::max({f[0].y, f[1].y, f[2].y, f[3].y}))));
}

void report_below_ground(const Wall& w, const std::array<Point2, 4>& f, Report& report) {
  report.add(make_diagnostic(
      Severity::error, Code::out_of_bounds, {w.id},
      fmt::format("{} starts at z = {}, below the site's floor (z = 0).", name_of(w),
                  metres(w.base)),
      fmt::format("raise its base by {}, or raise its level", metres_at_least(-w.base)),
      box_where(
          std::min({f[0].x, f[1].x, f[2].x, f[3].x}), std::min({f[0].y, f[1].y, f[2].y, f[3].y}),
          std::max({f[0].x, f[1].x, f[2].x, f[3].x}), std::max({f[0].y, f[1].y, f[2].y, f[3].y}))));
}

/// out_of_bounds of wall w; a chord of an arc wall `reported` already is not reported again.
void check_bounds(const ResolvedPlan& r, const Joins& joins, const Footprints& fp, std::size_t w,
                  std::vector<bool>& reported, Report& report) {
  const Plan& plan = r.plan;
  const bool inside = is_inside_site(plan.site, fp, w);
  const bool low = is_under_max_height(plan.site, plan.walls[w]);
  const bool above_ground = plan.walls[w].base >= 0;  // absolute: the levels are resolved
  if ((inside && low && above_ground) || reported[r.source_wall[w]]) return;
  reported[r.source_wall[w]] = true;
  const std::array<Point2, 4> f = approximate_footprint(plan, joins, w);
  if (!inside) report_outside_site(plan, f, plan.walls[w], report);
  if (!low) report_too_high(plan.site, plan.walls[w], f, report);
  if (!above_ground) report_below_ground(plan.walls[w], f, report);
}

}  // namespace

void check_geometry(const Plan& plan, const Usable& usable, const ResolvedPlan& resolved,
                    const Joins& joins, Report& report) {
  const Plan& g = resolved.plan;
  const Footprints fp(g, joins, resolved.usable.walls);
  check_overlaps(resolved, joins, fp, report);
  if (usable.site) {
    std::vector<bool> reported(plan.walls.size(), false);
    for (std::size_t w = 0; w < g.walls.size(); ++w)
      if (resolved.usable.walls[w]) check_bounds(resolved, joins, fp, w, reported, report);
  }
  check_openings(plan, usable, resolved, joins, fp, report);
  check_slabs(plan, usable, resolved, joins, fp, report);
  check_obstructions(usable, resolved, fp, report);
}

}  // namespace roomcad::detail
