// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/detail/wall_overlaps.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "geometry/segment_predicates.h"
#include "plan/plan_levels.h"
#include "repair/detail/frame_box.h"
#include "repair/detail/opening_places.h"

namespace roomcad::detail {
namespace {

/// Two walls of a finding: X, the one edited, and Y, the one kept, with X's box in Y's frame.
struct Pair {
  std::size_t x, y;
  const Wall& wx;
  const Wall& wy;
  LineFrame frame;
  FrameBox bx, by;
};

/// Wraps the edit of wall X (into `edited`, or its removal) with its openings' edits.
std::optional<Proposal> with_openings(const RepairContext& ctx, const Pair& p,
                                      const std::optional<Wall>& edited, RepairEdit wall_edit,
                                      std::string& reason) {
  const Placement placement = place_openings(ctx.plan, ctx.openings[p.x], p.wx, edited, p.wy,
                                             ctx.openings[p.y], ctx.tolerance);
  if (!placement.refusal.empty()) {
    reason = placement.refusal;
    return std::nullopt;
  }
  Proposal proposal;
  proposal.edits = placement.edits;
  proposal.edits.push_back(std::move(wall_edit));
  return proposal;
}

RepairEdit wall_edit(const Wall& before, const Wall& after, RepairChange change, double moves) {
  RepairEdit e{before.id, change, {}, {}, {}, moves};
  record_field(e, "from", before.from, after.from);
  record_field(e, "to", before.to, after.to);
  record_field(e, "base", before.base, after.base);
  record_field(e, "height", before.height, after.height);
  return e;
}

std::optional<Proposal> remove_inner(const RepairContext& ctx, const Pair& p, std::string& reason) {
  const double excess = p.bx.excess_over(p.by);
  if (excess > ctx.tolerance) return std::nullopt;
  RepairEdit e{p.wx.id, RepairChange::remove, {{"from", p.wx.from}, {"to", p.wx.to}}, {}, {},
               excess};
  return with_openings(ctx, p, std::nullopt, std::move(e), reason);
}

/// The wall's base field that puts its base at z (rounded up), and that z.
std::pair<double, long double> base_at(const Plan& plan, const Wall& w, long double z) {
  const long double elevation = level_elevation(plan, w.level);
  double base = static_cast<double>(z - elevation);
  while (static_cast<long double>(base_z(plan, Wall{.level = w.level, .base = base})) < z)
    base = std::nextafter(base, INFINITY);
  return {base, base_z(plan, Wall{.level = w.level, .base = base})};
}

/// X trimmed in height to meet Y, when Y covers X's footprint: X's top lowered to Y's base, or
/// X's base raised to Y's top.
std::optional<Proposal> trim_height(const RepairContext& ctx, const Pair& p, std::string& reason) {
  const double spill = std::hypot(p.by.s.excess(p.bx.s), p.by.n.excess(p.bx.n));
  if (spill > ctx.tolerance || !p.bx.z.overlaps(p.by.z)) return std::nullopt;
  Wall after = p.wx;
  const long double base = base_z(ctx.plan, p.wx);
  const long double top = base + p.wx.height;
  long double gap = 0;
  if (base < p.by.z.lo && top <= static_cast<long double>(p.by.z.lo) + p.wy.height) {
    after.height = static_cast<double>(p.by.z.lo - base);  // round down: no new overlap
    while (base + after.height > p.by.z.lo) after.height = std::nextafter(after.height, 0.0);
    gap = p.by.z.lo - (base + after.height);
  } else if (base >= p.by.z.lo && base < static_cast<long double>(p.by.z.lo) + p.wy.height &&
             top > static_cast<long double>(p.by.z.lo) + p.wy.height) {
    const long double y_top = static_cast<long double>(p.by.z.lo) + p.wy.height;
    const auto [new_base, new_z] = base_at(ctx.plan, p.wx, y_top);
    after.base = new_base;
    after.height = static_cast<double>(top - new_z);
    while (new_z + after.height > top) after.height = std::nextafter(after.height, 0.0);
    gap = (new_z - y_top) + (top - (new_z + after.height));
  } else {
    return std::nullopt;
  }
  if (!(after.height > 0)) return std::nullopt;
  const double moves = std::hypot(spill, static_cast<double>(gap));
  return with_openings(ctx, p, after, wall_edit(p.wx, after, RepairChange::trim, moves), reason);
}

/// X trimmed along its line to meet Y end to end, when Y covers X's width and height.
std::optional<Proposal> trim_length(const RepairContext& ctx, const Pair& p, std::string& reason) {
  const double spill = std::hypot(p.by.n.excess(p.bx.n), p.by.z.excess(p.bx.z));
  if (spill > ctx.tolerance) return std::nullopt;
  const bool x_before = p.bx.s.lo < p.by.s.lo && p.by.s.lo < p.bx.s.hi && p.bx.s.hi <= p.by.s.hi;
  const bool x_after = p.by.s.lo <= p.bx.s.lo && p.bx.s.lo < p.by.s.hi && p.by.s.hi < p.bx.s.hi;
  if (!x_before && !x_after) return std::nullopt;
  // The end of X inside Y goes to Y's end inside X: Y's end point itself on one line.
  const double target = x_before ? p.by.s.lo : p.by.s.hi;
  const Point2 y_end = p.frame.s(p.wy.from) == target ? p.wy.from : p.wy.to;
  const bool move_from = (p.frame.s(p.wx.from) > p.frame.s(p.wx.to)) == x_before;
  Wall after = p.wx;
  Point2& end = move_from ? after.from : after.to;
  double slip = 0;
  if (on_one_line(p.wx, p.wy)) {
    end = y_end;
  } else {
    const double shift = target - p.frame.s(end);
    end = {end.x + shift * p.frame.unit.x, end.y + shift * p.frame.unit.y};
    slip = std::fabs(p.frame.s(end) - target);
  }
  if (after.from == after.to) return std::nullopt;
  return with_openings(ctx, p, after,
                       wall_edit(p.wx, after, RepairChange::trim, std::hypot(spill, slip)), reason);
}

/// X moved across onto Y's line, when their lines are at most the tolerance apart.
std::optional<Proposal> snap_across(const RepairContext& ctx, const Pair& p) {
  const double offset = (p.frame.n(p.wx.from) + p.frame.n(p.wx.to)) / 2;
  if (offset == 0 || std::fabs(offset) > ctx.tolerance) return std::nullopt;
  const Point2 by{p.frame.unit.y * offset, -p.frame.unit.x * offset};
  Wall after = p.wx;
  after.from = {p.wx.from.x + by.x, p.wx.from.y + by.y};
  after.to = {p.wx.to.x + by.x, p.wx.to.y + by.y};
  for (const Point2 end : {p.wx.from, p.wx.to})
    if (ctx.joined_at(p.x, end, p.y)) return std::nullopt;
  Proposal proposal;
  proposal.edits.push_back(wall_edit(p.wx, after, RepairChange::snap, std::fabs(offset)));
  return proposal;  // openings ride along: their offsets are along the wall
}

}  // namespace

bool nearly_parallel(const RepairContext& ctx, const Wall& a, const Wall& b) {
  if (are_parallel(a.from, a.to, b.from, b.to)) return true;
  const LineFrame fa = line_frame(a), fb = line_frame(b);
  return std::fabs(fa.n(b.from) - fa.n(b.to)) <= ctx.tolerance &&
         std::fabs(fb.n(a.from) - fb.n(a.to)) <= ctx.tolerance;
}

namespace {

Attempt propose_parallel(const RepairContext& ctx, std::size_t a, std::size_t b) {
  Attempt attempt;
  std::string reason;
  for (const auto& [x, y] : {std::pair{b, a}, std::pair{a, b}}) {
    const Wall& wx = ctx.plan.walls[x];
    const Wall& wy = ctx.plan.walls[y];
    const LineFrame frame = line_frame(wy);
    const Pair p{
        x, y, wx, wy, frame, frame_box(ctx.plan, frame, wx), frame_box(ctx.plan, frame, wy)};
    for (auto* propose : {&remove_inner, &trim_height, &trim_length})
      if (auto proposal = propose(ctx, p, reason)) attempt.proposals.push_back(*proposal);
  }
  for (const auto& [x, y] : {std::pair{b, a}, std::pair{a, b}}) {
    const Wall& wy = ctx.plan.walls[y];
    const LineFrame frame = line_frame(wy);
    const Pair p{x,
                 y,
                 ctx.plan.walls[x],
                 wy,
                 frame,
                 frame_box(ctx.plan, frame, ctx.plan.walls[x]),
                 frame_box(ctx.plan, frame, wy)};
    if (auto proposal = snap_across(ctx, p)) attempt.proposals.push_back(*proposal);
  }
  if (attempt.proposals.empty())
    attempt.reason = reason.empty() ? "no removal or trim of one wall keeps the union of the two, "
                                      "and their lines are further apart than the tolerance"
                                    : reason;
  return attempt;
}

/// The point where the line through X's end `e` (along X) meets Y's centre line, if X's end is
/// inside Y and that point lies on Y's centre line.
std::optional<Proposal> end_onto_line(const RepairContext& ctx, std::size_t x, std::size_t y,
                                      bool from_end, std::string& reason) {
  const Wall& wx = ctx.plan.walls[x];
  const Wall& wy = ctx.plan.walls[y];
  const LineFrame fy = line_frame(wy);
  const LineFrame fx = line_frame(wx);
  const Point2 end = from_end ? wx.from : wx.to;
  const Point2 far = from_end ? wx.to : wx.from;
  const double length_y = wall_length(wy), half_y = wy.thickness / 2;
  const auto inside_y = [&](Point2 q) {
    return std::fabs(fy.n(q)) <= half_y && fy.s(q) >= 0 && fy.s(q) <= length_y;
  };
  if (!inside_y(end) || inside_y(far)) return std::nullopt;
  const Point2 across{-fy.unit.y, fy.unit.x};
  const double slope = fx.unit.x * across.x + fx.unit.y * across.y;
  if (slope == 0) return std::nullopt;
  const double step = -fy.n(end) / slope;
  const Point2 meet{end.x + step * fx.unit.x, end.y + step * fx.unit.y};
  if (fy.s(meet) < 0 || fy.s(meet) > length_y) return std::nullopt;
  if (const auto joined = ctx.joined_at(x, end, y)) {
    reason = fmt::format("the end of '{}' inside '{}' is joined to '{}'", wx.id, wy.id, *joined);
    return std::nullopt;
  }
  // The end's corners, before and after: inside Y, the move keeps the union.
  const Point2 side{-fx.unit.y * wx.thickness / 2, fx.unit.x * wx.thickness / 2};
  bool kept = true;
  for (const Point2 q : {end, meet})
    kept = kept && inside_y({q.x + side.x, q.y + side.y}) && inside_y({q.x - side.x, q.y - side.y});
  const double shift = std::fabs(step);
  const double moves = kept ? 0.0 : shift;
  if (moves > ctx.tolerance) {
    reason = too_far(moves, ctx.tolerance);
    return std::nullopt;
  }
  Wall after = wx;
  (from_end ? after.from : after.to) = meet;
  const bool longer = std::hypot(meet.x - far.x, meet.y - far.y) > wall_length(wx);
  const Placement placement =
      place_openings(ctx.plan, ctx.openings[x], wx, after, wy, ctx.openings[y], ctx.tolerance);
  if (!placement.refusal.empty()) {
    reason = placement.refusal;
    return std::nullopt;
  }
  Proposal proposal;
  proposal.edits = placement.edits;
  proposal.edits.push_back(
      wall_edit(wx, after, longer ? RepairChange::extend : RepairChange::trim, moves));
  return proposal;
}

Attempt propose_angled(const RepairContext& ctx, std::size_t a, std::size_t b) {
  Attempt attempt;
  std::string reason;
  for (const auto& [x, y] : {std::pair{b, a}, std::pair{a, b}})
    for (const bool from_end : {true, false})
      if (auto proposal = end_onto_line(ctx, x, y, from_end, reason))
        attempt.proposals.push_back(*proposal);
  if (attempt.proposals.empty())
    attempt.reason = reason.empty() ? "neither wall has an end inside the other to move onto "
                                      "its centre line"
                                    : reason;
  return attempt;
}

}  // namespace

Attempt propose_wall_overlap(const RepairContext& ctx, const Diagnostic& finding) {
  if (finding.objects.size() != 2) return refused("not a pair of walls");
  const auto a = ctx.wall(finding.objects[0]), b = ctx.wall(finding.objects[1]);
  if (!a || !b) return refused("not a pair of walls");
  return propose_wall_pair(ctx, *a, *b);
}

Attempt propose_wall_pair(const RepairContext& ctx, std::size_t a, std::size_t b) {
  const Wall& wa = ctx.plan.walls[a];
  const Wall& wb = ctx.plan.walls[b];
  if (!is_plain_wall(wa) || !is_plain_wall(wb))
    return refused("a curved or sloped wall is left as drawn");
  if (nearly_parallel(ctx, wa, wb)) return propose_parallel(ctx, a, b);
  return propose_angled(ctx, a, b);
}

}  // namespace roomcad::detail
