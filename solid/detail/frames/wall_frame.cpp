// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/frames/wall_frame.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string_view>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "core/flat_index.h"
#include "geometry/segment_predicates.h"
#include "solid/build_model.h"

namespace roomcad::detail {
namespace {

bool is_positive(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace

double resolvable_size(double m) { return 64.0 * (std::nextafter(m, INFINITY) - m); }

namespace {

WallFrame make_frame(const Plan& plan, const Joins& joins, std::size_t index) {
  const Wall& w = plan.walls[index];
  const double dx = w.to.x - w.from.x, dy = w.to.y - w.from.y;
  const double length = std::hypot(dx, dy);
  if (!is_positive(length) || !is_positive(w.thickness) || !is_positive(w.height) ||
      !std::isfinite(w.base))
    throw PreconditionError(
        fmt::format(
            "build_model: wall '{}' cannot be built: length {}, thickness {}, height {}, base {} "
            "(length, thickness and height must be positive and finite)",
            w.id, length, w.thickness, w.height, w.base),
        Code::not_buildable);
  WallFrame f;
  f.wall = index;
  f.id = w.id;
  f.from = w.from;
  f.to = w.to;
  f.dir = {dx / length, dy / length};
  f.normal = {-f.dir.y, f.dir.x};
  f.length = length;
  f.half = w.thickness / 2.0;
  f.base = w.base;
  f.heights = {w.height, w.height_at_end.value_or(w.height)};
  if (!is_positive(f.heights[1]))
    throw PreconditionError(
        fmt::format("build_model: wall '{}' cannot be built: height_at_end {} (must be "
                    "positive and finite)",
                    w.id, f.heights[1]),
        Code::not_buildable);
  const double reach =
      std::max({std::abs(w.from.x), std::abs(w.from.y), std::abs(w.to.x), std::abs(w.to.y)}) +
      w.thickness;
  const double top = std::abs(w.base) + highest_height(w);
  const double smallest = std::max(resolvable_size(reach), resolvable_size(top));
  const double lowest = std::min(f.heights[0], f.heights[1]);
  if (length < smallest || w.thickness < smallest || lowest < smallest)
    throw PreconditionError(fmt::format("build_model: wall '{}' cannot be built: its length {}, "
                                        "thickness {} and height {} must each be "
                                        "at least {}, 64 units in the last place of its "
                                        "coordinates ({} m from the origin) and of its "
                                        "top ({} m); make it larger or delete it",
                                        w.id, length, w.thickness, lowest, smallest, reach, top),
                            Code::not_buildable);
  f.resolution = smallest;
  f.top = w.base + w.height;
  f.top_end = w.base + f.heights[1];
  f.capless = {joins.mitre[index][0].has_value(), joins.mitre[index][1].has_value()};
  f.footprint = wall_footprint(plan, joins, index);
  f.top_max = std::max(f.top, f.top_end);
  if (is_sloped(f)) {  // the plane over the footprint's corners (mitres reach past the ends)
    for (const Point2& c : f.footprint) {
      const double u = (c.x - f.from.x) * f.dir.x + (c.y - f.from.y) * f.dir.y;
      f.top_max = std::max(f.top_max, f.top + (f.heights[1] - f.heights[0]) * u / length);
    }
    f.top_max += 1e-9 * (1.0 + std::abs(f.top_max));  // the doubles above round; a bound must not
  }
  f.color = w.color;
  return f;
}

}  // namespace

Box2 footprint_box(const WallFrame& f, double margin) {
  Box2 b{f.footprint[0].x, f.footprint[0].y, f.footprint[0].x, f.footprint[0].y, f.wall};
  for (const Point2& p : f.footprint) {
    b.min_x = std::min(b.min_x, p.x), b.max_x = std::max(b.max_x, p.x);
    b.min_y = std::min(b.min_y, p.y), b.max_y = std::max(b.max_y, p.y);
  }
  b.min_x -= margin, b.min_y -= margin, b.max_x += margin, b.max_y += margin;
  return b;
}

SpaceBox footprint_space_box(const WallFrame& f) {
  return space_box(footprint_box(f), f.base, f.top_max);
}

namespace {

Hole make_hole(const Plan& plan, std::size_t index, const WallFrame& f) {
  const Opening& o = plan.openings[index];
  const Wall& w = plan.walls[f.wall];
  // An edge within the wall's resolution of its end, base or flat top is flush with it: the
  // sliver of wall left between them could not be written apart from the hole (stress
  // finding S6: an opening 1e-16 m short of a short wall's end built a solid that was open).
  const double r = f.resolution;
  // Under a sloped top the general path cuts whatever the hole meets (validation judged the
  // outline exactly); a flat wall's fast path needs the rectangle inside.
  const bool inside = is_positive(o.width) && is_positive(o.height) && std::isfinite(o.offset) &&
                      std::isfinite(o.sill) && o.offset >= -r &&
                      o.offset + o.width <= f.length + r && o.sill >= -r &&
                      (is_sloped(f) || o.sill + o.height <= w.height + r);
  if (!inside)
    throw PreconditionError(
        fmt::format(
            "build_model: opening '{}' cannot be cut: u [{}, {}] x v [{}, {}] is not a non-empty "
            "rectangle inside wall '{}' ([0, {}] x [0, {}])",
            o.id, o.offset, o.offset + o.width, o.sill, o.sill + o.height, w.id, f.length,
            std::max(f.heights[0], f.heights[1])),
        Code::not_buildable);
  for (std::size_t k = 0; k < 4; ++k)
    if (f.footprint[k] == f.footprint[(k + 1) % 4])
      throw PreconditionError(fmt::format("build_model: opening '{}' cannot be cut: wall '{}' is "
                                          "shorter than its mitres (a side "
                                          "of its footprint has no length)",
                                          o.id, w.id),
                              Code::not_buildable);
  // Both edges snap alike (0 first), so u0 <= u1 and z0 <= z1 stay so. base + (sill + height)
  // equals the wall's top (f.top) exactly when the opening reaches it.
  const auto snap = [r](double x, double end) { return x < r ? 0.0 : end - x < r ? end : x; };
  const double top = is_sloped(f) ? INFINITY : w.height;
  return {.opening = index,
          .u0 = snap(o.offset, f.length),
          .u1 = snap(o.offset + o.width, f.length),
          .z0 = w.base + snap(o.sill, top),
          .z1 = w.base + snap(o.sill + o.height, top),
          .width = o.width,
          .height = o.height,
          .shape = o.shape};
}

// Ends meeting at one point, keyed by its bits (as find_hubs does).
using NodeKey = std::pair<std::uint64_t, std::uint64_t>;

// Outward directions of two wall ends at one node that run on from each other within
// kHairline radians (but not exactly: then the square ends coincide), the walls sharing a
// height range (a wall under the node's floor is not part of its join).
bool is_hairline_pair(const Wall& a, WallEnd ea, const Wall& b, WallEnd eb) {
  constexpr double kHairline = 1e-6;
  auto outward = [](const Wall& w, WallEnd e) {
    const double dx = w.to.x - w.from.x, dy = w.to.y - w.from.y, len = std::hypot(dx, dy);
    return e == WallEnd::from ? Point2{dx / len, dy / len} : Point2{-dx / len, -dy / len};
  };
  const Point2 da = outward(a, ea), db = outward(b, eb);
  const double cross = da.x * db.y - da.y * db.x, dot = da.x * db.x + da.y * db.y;
  return a.thickness == b.thickness && dot < 0.0 && cross != 0.0 && std::abs(cross) <= kHairline &&
         share_heights(a, b);  // one above the other they do not meet
}

// Where three or more walls meet at a node (a unite join), two of equal thickness that run
// on from each other within a hairline angle would leave a wedge between their square ends,
// about half * angle wide: far below a millimetre, yet no mesh in doubles can hold it. Such
// a pair is mitred instead (its ends move by at most half * angle), which closes the wedge
// exactly: both take the same rounded corners. @return the joins with those mitres.
Joins with_hairline_mitres(const Plan& plan, Joins joins) {
  std::map<NodeKey, std::vector<std::pair<std::size_t, WallEnd>>> nodes;
  for (std::size_t i = 0; i < plan.walls.size(); ++i)
    for (const WallEnd e : {WallEnd::from, WallEnd::to}) {
      const Point2& p = e == WallEnd::from ? plan.walls[i].from : plan.walls[i].to;
      nodes[{std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0)}]
          .emplace_back(i, e);
    }
  for (const auto& [key, ends] : nodes) {
    if (ends.size() < 3) continue;
    for (const auto& [i, ei] : ends)
      for (const auto& [j, ej] : ends) {
        auto& mi = joins.mitre[i][static_cast<std::size_t>(ei)];
        auto& mj = joins.mitre[j][static_cast<std::size_t>(ej)];
        if (i >= j || mi || mj || !is_hairline_pair(plan.walls[i], ei, plan.walls[j], ej)) continue;
        mi = j, mj = i;
      }
  }
  return joins;
}

}  // namespace

std::vector<WallFrame> make_wall_frames(const Plan& plan, const Joins& plan_joins,
                                        std::span<const std::array<bool, 2>> through_mitre) {
  const Joins joins = with_hairline_mitres(plan, plan_joins);
  // Frames are independent (a skewed wall's exact corners cost tens of microseconds): built
  // in parallel, the first wall that cannot be built (in plan order) reported.
  std::vector<WallFrame> frames(plan.walls.size());
  std::vector<std::optional<PreconditionError>> failures(plan.walls.size());
  tbb::parallel_for(std::size_t{0}, plan.walls.size(), [&](std::size_t i) {
    try {
      frames[i] = make_frame(plan, joins, i);
    } catch (const PreconditionError& e) {
      failures[i] = e;
    }
  });
  for (const auto& failure : failures)
    if (failure) throw *failure;
  const IdIndex by_id = index_by_id(plan.walls);
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    const std::uint32_t w = by_id.find(plan.openings[i].wall);
    if (w == by_id.kNone)
      throw PreconditionError(fmt::format("build_model: opening '{}' cannot be cut: its wall '{}' "
                                          "does not exist",
                                          plan.openings[i].id, plan.openings[i].wall),
                              Code::not_buildable);
    Hole& hole = frames[w].holes.emplace_back(make_hole(plan, i, frames[w]));
    if (i < through_mitre.size()) hole.through_mitre = through_mitre[i];
  }
  for (WallFrame& f : frames)
    std::sort(f.holes.begin(), f.holes.end(), [](const Hole& a, const Hole& b) {
      return a.u0 < b.u0 || (a.u0 == b.u0 && a.z0 < b.z0);
    });
  return frames;
}

bool needs_general_path(const WallFrame& f) {
  return is_sloped(f) || std::any_of(f.holes.begin(), f.holes.end(),
                                     [](const Hole& h) { return !h.shape.empty(); });
}

Point2 side_point(const WallFrame& f, double u, int side) {
  const double w = side * f.half;
  return {f.from.x + f.dir.x * u + f.normal.x * w, f.from.y + f.dir.y * u + f.normal.y * w};
}

}  // namespace roomcad::detail
