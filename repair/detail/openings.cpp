// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/detail/openings.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/box.h"
#include "geometry/segment_predicates.h"
#include "plan/plan_levels.h"
#include "repair/detail/frame_box.h"
#include "repair/detail/wall_overlaps.h"

namespace roomcad::detail {
namespace {

/// The smallest double >= a + b, and the largest <= a - b: an opening's new edge never
/// rounds back into what it was moved off.
double sum_up(double a, double b) {
  double s = a + b;
  while (static_cast<long double>(s) < static_cast<long double>(a) + b)
    s = std::nextafter(s, INFINITY);
  return s;
}
double difference_down(double a, double b) {
  double d = a - b;
  while (static_cast<long double>(d) > static_cast<long double>(a) - b)
    d = std::nextafter(d, -INFINITY);
  return d;
}

RepairEdit opening_edit(const Opening& before, const Opening& after, RepairChange change,
                        double moves) {
  RepairEdit e{before.id, change, {}, {}, {}, moves};
  record_field(e, "offset", before.offset, after.offset);
  record_field(e, "width", before.width, after.width);
  record_field(e, "sill", before.sill, after.sill);
  record_field(e, "height", before.height, after.height);
  return e;
}

Attempt one_edit(RepairEdit edit, double tolerance) {
  if (edit.moves > tolerance) return refused(too_far(edit.moves, tolerance));
  Proposal p;
  p.edits.push_back(std::move(edit));
  return {{std::move(p)}, {}};
}

/// A wall's length rounded down, so that an opening shortened to it fits the exact length.
double length_within(const Wall& w) {
  return std::nextafter(std::nextafter(wall_length(w), 0.0), 0.0);
}

Attempt fit_in_wall(const RepairContext& ctx, const Opening& o, const Wall& w) {
  if (!o.shape.empty()) return refused("a shaped opening is left as drawn");
  const double length = length_within(w);
  Opening after = o;
  after.offset = std::max(o.offset, 0.0);
  const double end =
      std::min(static_cast<double>(static_cast<long double>(o.offset) + o.width), length);
  after.width = difference_down(end, after.offset);
  const double top =
      std::min(static_cast<double>(static_cast<long double>(o.sill) + o.height), w.height);
  after.height = difference_down(top, o.sill);
  if (!(after.width > 0 && after.height > 0)) return refused("nothing of it lies in its wall");
  const double moves =
      std::max({after.offset - o.offset, o.width - after.width, o.height - after.height});
  return one_edit(opening_edit(o, after, RepairChange::shorten, moves), ctx.tolerance);
}

Attempt separate(const RepairContext& ctx, std::size_t ia, std::size_t ib) {
  const Opening& a = ctx.plan.openings[ia];
  const Opening& b = ctx.plan.openings[ib];
  if (!a.shape.empty() || !b.shape.empty()) return refused("a shaped opening is left as drawn");
  const auto end = [](const Opening& o) { return static_cast<long double>(o.offset) + o.width; };
  const auto top = [](const Opening& o) { return static_cast<long double>(o.sill) + o.height; };
  const auto inside = [&](const Opening& i, const Opening& o) {
    return o.offset <= i.offset && end(i) <= end(o) && o.sill <= i.sill && top(i) <= top(o);
  };
  for (const Opening* inner : {&b, &a}) {
    const Opening& outer = inner == &b ? a : b;
    if (!inside(*inner, outer)) continue;
    Proposal p;
    p.edits.push_back({inner->id, RepairChange::remove, {{"wall", inner->wall}}, {}, {}, 0.0});
    return {{std::move(p)}, {}};
  }
  if (a.type == b.type && a.sill == b.sill && a.height == b.height) {
    Opening merged = a;
    merged.offset = std::min(a.offset, b.offset);
    const long double far = std::max(end(a), end(b));
    merged.width = static_cast<double>(far - merged.offset);
    if (merged.offset + static_cast<long double>(merged.width) == far) {
      Proposal p;
      p.edits.push_back({b.id, RepairChange::remove, {{"wall", b.wall}}, {}, {}, 0.0});
      p.edits.push_back(opening_edit(a, merged, RepairChange::merge, 0.0));
      return {{std::move(p)}, {}};
    }
  }
  Opening after = b;  // the later one gives way along the wall
  if (b.offset >= a.offset) {
    after.offset = sum_up(a.offset, a.width);
    after.width = static_cast<double>(end(b) - after.offset);
  } else {
    after.width = difference_down(a.offset, b.offset);
  }
  if (!(after.width > 0)) return refused("the later opening lies within the first along the wall");
  return one_edit(opening_edit(b, after, RepairChange::shorten, b.width - after.width),
                  ctx.tolerance);
}

/// The box of the part of wall `w`'s hole prism over [s0, s1] along it, [z0, z1] up.
Box3 prism_box(const Plan& plan, const Wall& w, double s0, double s1, double z0, double z1) {
  const LineFrame f = line_frame(w);
  const Point2 side{-f.unit.y * w.thickness / 2, f.unit.x * w.thickness / 2};
  const double base = base_z(plan, w);
  Box3 box = empty_box3();
  for (const double s : {s0, s1})
    for (const double sign : {1.0, -1.0}) {
      const Point2 c = f.at(s);
      add_point(box, c.x + sign * side.x, c.y + sign * side.y, base + z0);
      add_point(box, c.x + sign * side.x, c.y + sign * side.y, base + z1);
    }
  return box;
}

/// @return the id of an opening other than `o` whose hole comes within `gap` of `strip`: the
///         strip that shortening `o` gives back to its wall would stand as a sliver between
///         two holes (one door split over two walls), not as wall beside a hole.
std::optional<std::string> hole_beside(const RepairContext& ctx, const Opening& o,
                                       const Box3& strip, double gap) {
  for (const Opening& other : ctx.plan.openings) {
    if (other.id == o.id) continue;
    const auto host = ctx.wall(other.wall);
    if (!host || !is_plain_wall(ctx.plan.walls[*host])) continue;
    const Box3 hole = prism_box(ctx.plan, ctx.plan.walls[*host], other.offset,
                                other.offset + other.width, other.sill, other.sill + other.height);
    bool near = true;
    for (std::size_t k = 0; k < 3; ++k)
      near = near && hole.low[k] <= strip.high[k] + gap && strip.low[k] <= hole.high[k] + gap;
    if (near) return other.id;
  }
  return std::nullopt;
}

Attempt clear_of_blocker(const RepairContext& ctx, const Opening& o, std::size_t host,
                         std::size_t blocker) {
  if (ctx.overlap(host, blocker)) return refused("left to the repair of the two walls' overlap");
  const Wall& h = ctx.plan.walls[host];
  const Wall& x = ctx.plan.walls[blocker];
  if (!is_plain_wall(h) || !is_plain_wall(x)) return refused("a curved or sloped wall");
  if (nearly_parallel(ctx, h, x)) {
    // A wall drawn over the host (that validation joins, so reports no overlap): the walls'
    // repair, which keeps every hole where it is.
    Attempt walls = propose_wall_pair(ctx, host, blocker);
    if (!walls.proposals.empty()) return walls;
  }
  if (!o.shape.empty()) return refused("a shaped opening is left as drawn");
  const LineFrame frame = line_frame(h);
  const LineFrame fx = line_frame(x);
  const Point2 side{-fx.unit.y * x.thickness / 2, fx.unit.x * x.thickness / 2};
  Extent span{INFINITY, -INFINITY};
  for (const Point2 end : {x.from, x.to})
    for (const double sign : {1.0, -1.0}) {
      const double s = frame.s({end.x + sign * side.x, end.y + sign * side.y});
      span = {std::min(span.lo, s), std::max(span.hi, s)};
    }
  const double start = o.offset,
               stop = static_cast<double>(static_cast<long double>(o.offset) + o.width);
  Opening after = o;
  if (span.lo <= start && start < span.hi && span.hi < stop) {
    after.offset = span.hi;
    after.width = difference_down(stop, span.hi);
  } else if (start < span.lo && span.lo < stop && stop <= span.hi) {
    after.width = difference_down(span.lo, start);
  } else {
    return refused(fmt::format("wall '{}' crosses the middle of its hole, or all of it", x.id));
  }
  const double kept_lo = after.offset, kept_hi = after.offset + after.width;
  const Box3 strip = kept_lo > start
                         ? prism_box(ctx.plan, h, start, kept_lo, o.sill, o.sill + o.height)
                         : prism_box(ctx.plan, h, kept_hi, stop, o.sill, o.sill + o.height);
  if (const auto beside = hole_beside(ctx, o, strip, ctx.tolerance))
    return refused(
        fmt::format("the strip it would give back to its wall lies beside the hole of "
                    "'{}' (one opening drawn over two walls)",
                    *beside));
  return one_edit(opening_edit(o, after, RepairChange::shorten, o.width - after.width),
                  ctx.tolerance);
}

}  // namespace

Attempt propose_opening_fix(const RepairContext& ctx, const Diagnostic& finding) {
  const auto opening = finding.objects.empty() ? std::nullopt : ctx.opening(finding.objects[0]);
  if (!opening) return refused("not an opening of the plan");
  const Opening& o = ctx.plan.openings[*opening];
  const auto host = ctx.wall(o.wall);
  if (!host || !is_plain_wall(ctx.plan.walls[*host]))
    return refused("its wall is curved or sloped, or missing");
  switch (finding.code) {
    case Code::opening_outside_wall: return fit_in_wall(ctx, o, ctx.plan.walls[*host]);
    case Code::opening_overlap: {
      const auto other =
          finding.objects.size() == 2 ? ctx.opening(finding.objects[1]) : std::nullopt;
      if (!other) return refused("not a pair of openings");
      return separate(ctx, *opening, *other);
    }
    default: break;
  }
  const auto blocker = finding.objects.size() == 3 ? ctx.wall(finding.objects[2]) : std::nullopt;
  if (!blocker) return refused("blocked by a slab: left as drawn");
  return clear_of_blocker(ctx, o, *host, *blocker);
}

}  // namespace roomcad::detail
