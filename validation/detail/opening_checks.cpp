// SPDX-License-Identifier: GPL-3.0-or-later
// opening_outside_wall, opening_overlap and opening_blocked.
//
// An opening is the rectangle [offset, offset + width] x [sill, sill + height] in its wall's
// (u along from->to, v up from the base) frame; its hole goes through the full thickness.
// The hole is blocked when it shares interior volume with ANOTHER wall's mitred solid,
// joined walls included (a door right at a T junction opens into the stem of the T).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "geometry/polygon_predicates.h"
#include "plan/arc_chords.h"
#include "plan/plan_chords.h"
#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"
#include "validation/detail/resolved_plan.h"
#include "validation/detail/shapes.h"

namespace roomcad::detail {
namespace {

double length_of(const Wall& w) { return std::hypot(w.to.x - w.from.x, w.to.y - w.from.y); }

/// The hole's corners in doubles (for messages and `where`).
std::array<Point2, 4> hole_points(const Wall& w, const Opening& o) {
  const double length = length_of(w);
  const Point2 u{(w.to.x - w.from.x) / length, (w.to.y - w.from.y) / length};
  const Point2 n{-u.y * w.thickness / 2, u.x * w.thickness / 2};
  const auto at = [&](double t, double side) {
    return Point2{w.from.x + t * u.x + side * n.x, w.from.y + t * u.y + side * n.y};
  };
  const double end = o.offset + o.width;
  return {at(o.offset, -1), at(end, -1), at(end, 1), at(o.offset, 1)};
}

Where bounds_where(const std::array<Point2, 4>& q) {
  const auto [lx, hx] = std::minmax({q[0].x, q[1].x, q[2].x, q[3].x});
  const auto [ly, hy] = std::minmax({q[0].y, q[1].y, q[2].y, q[3].y});
  return box_where(lx, ly, hx, hy);
}

Where opening_where(const Wall& w, const Opening& o) { return bounds_where(hole_points(w, o)); }

/// One failed side of an opening's fit in its wall: what is wrong and how to fix it.
struct Misfit {
  std::string problem;
  std::string fix;
};

/// The corners of an opening's outline in its unit square: its shape, or the rectangle's.
const Polygon& outline_of(const Opening& o) {
  static const Polygon kRectangle{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return o.shape.empty() ? kRectangle : o.shape;
}

/// A wall as the openings see it: its centre line (an arc's chords) and its length along it.
struct Host {
  const Wall& wall;
  std::vector<Point2> line;
  double length;  ///< doubles, for messages
};

Host host_of(const Plan& plan, const Wall& w) {
  const double tolerance = chord_tolerance_of(plan.site);
  std::vector<Point2> line = is_buildable_arc(w, tolerance) ? chord_polyline(w, tolerance)
                                                            : std::vector<Point2>{w.from, w.to};
  const double length = polyline_length(line);
  return {w, std::move(line), length};
}

/// The exact length of the host's polyline.
template <class NT>
NT exact_length(const Host& h) {
  NT length(0);
  for (std::size_t k = 1; k < h.line.size(); ++k) {
    const exact::Pt<NT> d = exact::to_pt<NT>(h.line[k]) - exact::to_pt<NT>(h.line[k - 1]);
    length = length + exact::root(exact::dot(d, d));
  }
  return length;
}

/// How far (doubles) the outline of `o` reaches above the host's (sloped) top, at most.
double height_over_top(const Host& h, const Opening& o) {
  const double rise = h.wall.height_at_end.value_or(h.wall.height) - h.wall.height;
  double over = -INFINITY;
  for (const Point2& p : outline_of(o)) {
    const double u = o.offset + p.x * o.width;
    over = std::max(over, o.sill + p.y * o.height - (h.wall.height + rise * u / h.length));
  }
  return over;
}

std::vector<Misfit> find_misfits(const Host& h, const Opening& o) {
  const Wall& w = h.wall;
  const Polygon& outline = outline_of(o);
  std::vector<Misfit> out;
  const double length = h.length;
  double u_lo = INFINITY, u_hi = -INFINITY;
  for (const Point2& p : outline) {
    u_lo = std::min(u_lo, o.offset + p.x * o.width);
    u_hi = std::max(u_hi, o.offset + p.x * o.width);
  }
  // Each side is decided exactly at the outline's corners: the wall's face is convex (a
  // trapezoid under a sloped top), so the outline is inside it iff its corners are.
  const auto all_corners = [&](auto&& inside) {
    return std::all_of(outline.begin(), outline.end(), [&](const Point2& p) {
      return exact::decide([&](auto tag) { return inside(decltype(tag)(), p); });
    });
  };
  const bool starts_in = all_corners([&](auto nt, const Point2& p) {
    using NT = decltype(nt);
    return NT(o.offset) + NT(p.x) * NT(o.width) >= NT(0);
  });
  const bool ends_in = all_corners([&](auto nt, const Point2& p) {
    using NT = decltype(nt);
    return NT(o.offset) + NT(p.x) * NT(o.width) <= exact_length<NT>(h);
  });
  const bool top_in = all_corners([&](auto nt, const Point2& p) {
    using NT = decltype(nt);
    const NT v = NT(o.sill) + NT(p.y) * NT(o.height);
    if (!w.height_at_end) return v <= NT(w.height);
    // v <= height + rise * u / length, multiplied out by the (positive) length.
    const NT u = NT(o.offset) + NT(p.x) * NT(o.width);
    const NT rise = NT(*w.height_at_end) - NT(w.height);
    return (v - NT(w.height)) * exact_length<NT>(h) <= rise * u;
  });
  if (!starts_in)
    out.push_back({fmt::format("starts {} before the start of {}", metres(-u_lo), name_of(w)),
                   fmt::format("move it {} toward the end", metres_at_least(-u_lo))});
  if (!ends_in) {
    const double past = u_hi - length;
    const double fits = length - std::max(o.offset, 0.0);
    out.push_back({fmt::format("ends {} past the end of {} ({} long)", metres(past), name_of(w),
                               metres(length)),
                   o.offset - past >= 0
                       ? fmt::format("move it {} toward the start, or make it {} wide",
                                     metres_at_least(past), metres_at_most(o.width - past))
                       : fmt::format("make it at most {} wide", metres_at_most(fits))});
  }
  if (!top_in) {
    const double over = height_over_top(h, o);
    const std::string top = w.height_at_end ? fmt::format("{} to {} high, sloped", metres(w.height),
                                                          metres(*w.height_at_end))
                                            : fmt::format("{} high", metres(w.height));
    out.push_back(
        {fmt::format("reaches {} above the top of {} ({})", metres(over), name_of(w), top),
         fmt::format("make it {} high or lower its sill by that much",
                     metres_at_most(o.height - over))});
  }
  return out;
}

void check_fit(const Plan& plan, const Wall& w, const Opening& o, Report& report) {
  const std::vector<Misfit> misfits = find_misfits(host_of(plan, w), o);
  if (misfits.empty()) return;
  std::vector<std::string> problems, fixes;
  for (const Misfit& m : misfits) {
    problems.push_back(m.problem);
    fixes.push_back(m.fix);
  }
  report.add(make_diagnostic(Severity::error, Code::opening_outside_wall, {o.id, w.id},
                             fmt::format("{} {}.", name_of(o), fmt::join(problems, ", and ")),
                             fmt::format("{}", fmt::join(fixes, "; ")), opening_where(w, o)));
}

bool openings_overlap(const Opening& a, const Opening& b) {
  if (!a.shape.empty() || !b.shape.empty()) return outlines_overlap(a, b);
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    return static_cast<bool>(spans_overlap(NT(a.offset), NT(a.offset) + NT(a.width), NT(b.offset),
                                           NT(b.offset) + NT(b.width))) &&
           static_cast<bool>(spans_overlap(NT(a.sill), NT(a.sill) + NT(a.height), NT(b.sill),
                                           NT(b.sill) + NT(b.height)));
  });
}

void report_opening_overlap(const Wall& w, const Opening& a, const Opening& b, Report& report) {
  const double shared =
      std::min(a.offset + a.width, b.offset + b.width) - std::max(a.offset, b.offset);
  report.add(make_diagnostic(
      Severity::error, Code::opening_overlap, {a.id, b.id},
      fmt::format("{} and {} in {} overlap over {} along the wall.", name_of(a), name_of(b),
                  name_of(w), metres(shared)),
      fmt::format(
          "move {} {} toward the end of the wall (offset {:.2f}), or narrow {} by that much", b.id,
          metres_at_least(a.offset + a.width - b.offset),
          std::ceil((a.offset + a.width) * 100 - 1e-7) / 100, a.id),
      opening_where(w, b)));
}

/// Sweep along each wall: openings sorted by offset are compared while the next one starts
/// before the current one's end (rounded up, so no overlapping pair is skipped).
void check_overlapping_openings(const Plan& plan, const Usable& usable, Report& report) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < plan.openings.size(); ++i)
    if (usable.host[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    const Opening& a = plan.openings[x];
    const Opening& b = plan.openings[y];
    return std::tie(*usable.host[x], a.offset, x) < std::tie(*usable.host[y], b.offset, y);
  });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Opening& a = plan.openings[order[i]];
    const double end = std::nextafter(a.offset + a.width, INFINITY);
    for (std::size_t j = i + 1;
         j < order.size() && usable.host[order[j]] == usable.host[order[i]] &&
         plan.openings[order[j]].offset < end;
         ++j)
      if (openings_overlap(a, plan.openings[order[j]]))
        report_opening_overlap(plan.walls[*usable.host[order[i]]], a, plan.openings[order[j]],
                               report);
  }
}

bool is_blocked_by(const Plan& plan, const Footprints& fp, const Opening& o, std::size_t host,
                   std::size_t other) {
  const Wall& h = plan.walls[host];
  const Wall& x = plan.walls[other];
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    const NT bottom = NT(h.base) + NT(o.sill);
    if (!spans_overlap(bottom, bottom + NT(o.height), NT(x.base),
                       NT(x.base) + NT(highest_height(x))))
      return false;
    return interiors_overlap(hole_corners<NT>(h, o), fp.get<NT>(other));
  });
}

/// The offsets at which the opening would clear `blocker` along its wall, as a fix.
std::string clearing_fix(const Wall& host, const Opening& o, const std::array<Point2, 4>& blocker,
                         const Wall& other) {
  const double length = length_of(host);
  const Point2 u{(host.to.x - host.from.x) / length, (host.to.y - host.from.y) / length};
  double lo = INFINITY, hi = -INFINITY;
  for (const Point2& c : blocker) {
    const double t = (c.x - host.from.x) * u.x + (c.y - host.from.y) * u.y;
    lo = std::min(lo, t), hi = std::max(hi, t);
  }
  // Rounded to centimetres away from the blocker, so that the offset given really clears it.
  const double before = std::floor((lo - o.width) * 100) / 100;
  const double after = std::ceil(hi * 100) / 100;
  std::vector<std::string> options;
  if (before >= 0) options.push_back(fmt::format("offset {:.2f} (before it)", before));
  if (after + o.width <= length) options.push_back(fmt::format("offset {:.2f} (after it)", after));
  if (options.empty()) return fmt::format("move {} or {} so that they do not meet", other.id, o.id);
  return fmt::format("move {} along {} clear of {}: {}", o.id, host.id, other.id,
                     fmt::join(options, " or "));
}

void report_blocked(const Plan& plan, const Joins& joins, const Opening& o, std::size_t host,
                    std::size_t other, Report& report) {
  const Wall& h = plan.walls[host];
  const Wall& x = plan.walls[other];
  const std::array<Point2, 4> hole = hole_points(h, o);
  const std::array<Point2, 4> blocker = approximate_footprint(plan, joins, other);
  report.add(
      make_diagnostic(Severity::error, Code::opening_blocked, {o.id, h.id, x.id},
                      fmt::format("{} in {} is blocked: {} fills its hole {} deep.", name_of(o),
                                  name_of(h), name_of(x), metres(penetration(hole, blocker).first)),
                      clearing_fix(h, o, blocker, x), bounds_where(hole)));
}

void check_blocked_openings(const ResolvedPlan& r, const Joins& joins, const Footprints& fp,
                            Report& report) {
  const Plan& plan = r.plan;
  const Usable& usable = r.usable;
  std::vector<Box2> holes;
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    if (!usable.host[i]) continue;
    CGAL::Protect_FPU_rounding<true> upward;
    holes.push_back(
        box_of(hole_corners<exact::Approx>(plan.walls[*usable.host[i]], plan.openings[i]), i));
  }
  for (const auto& [i, other] : find_meeting_boxes(holes, fp.boxes())) {
    const std::size_t host = *usable.host[i];
    // The chords of an arc wall carry its openings' holes along the arc: not blockers.
    if (r.source_wall[other] != r.source_wall[host] &&
        is_blocked_by(plan, fp, plan.openings[i], host, other))
      report_blocked(plan, joins, plan.openings[i], host, other, report);
  }
}

}  // namespace

void check_openings(const Plan& plan, const Usable& usable, const ResolvedPlan& resolved,
                    const Joins& joins, const Footprints& footprints, Report& report) {
  for (std::size_t i = 0; i < plan.openings.size(); ++i)
    if (usable.host[i]) check_fit(plan, plan.walls[*usable.host[i]], plan.openings[i], report);
  check_overlapping_openings(plan, usable, report);
  check_blocked_openings(resolved, joins, footprints, report);
}

}  // namespace roomcad::detail
