// SPDX-License-Identifier: GPL-3.0-or-later
// Door leaves and clear rectangles against walls and each other, decided exactly on the
// written numbers (written_number.h).
#include "validation/rules/door_tests.h"

#include <algorithm>

#include "validation/rules/context.h"
#include "validation/rules/door_geometry.h"

namespace roomcad::rules {
namespace {

/// @return true if the open height ranges (a_lo, a_lo + a_h) and (b_lo, b_lo + b_h) overlap.
template <class NT>
bool heights_overlap(const NT& a_lo, const NT& a_h, const NT& b_lo, const NT& b_h) {
  return static_cast<bool>(a_lo < b_lo + b_h) && static_cast<bool>(b_lo < a_lo + a_h);
}

Box2 box_of(const Poly<WrittenApprox>& p) {
  Box2 b{p[0].x.value().inf(), p[0].y.value().inf(), p[0].x.value().sup(), p[0].y.value().sup(), 0};
  for (std::size_t i = 1; i < p.n; ++i) {
    b.min_x = std::min(b.min_x, p[i].x.value().inf()),
    b.max_x = std::max(b.max_x, p[i].x.value().sup());
    b.min_y = std::min(b.min_y, p[i].y.value().inf()),
    b.max_y = std::max(b.max_y, p[i].y.value().sup());
  }
  return b;
}

}  // namespace

bool leaf_hits_wall(const Scene& scene, const Opening& o, std::size_t host, std::size_t wall,
                    Precision precision) {
  const Plan& plan = scene.plan();
  const Wall& h = plan.walls[host];
  const Wall& x = plan.walls[wall];
  return evaluate(precision, [&](auto tag) {
    using NT = decltype(tag);
    if (!heights_overlap(NT(h.base) + NT(o.sill), NT(o.height), NT(x.base), NT(x.height)))
      return false;
    const LeafSweep<NT> leaf = leaf_sweep<NT>(h, o, o.hinge, o.swing);
    const Poly<NT> footprint = wall_polygon<NT>(plan, scene.joins(), wall);
    // Apart on some axis for sure: decided without clipping (whose branches the intervals
    // cannot take where a corner of the wall lies on the leaf's square, as mitres put it).
    if (is_surely(is_separated(footprint, leaf.square, false))) return false;
    return disc_meets_interior(leaf.hinge, leaf.radius2, clip(footprint, leaf.square));
  });
}

bool leaves_meet(const Scene& scene, const Opening& a, std::size_t host_a, const Opening& b,
                 std::size_t host_b, Precision precision) {
  const Wall& ha = scene.plan().walls[host_a];
  const Wall& hb = scene.plan().walls[host_b];
  return evaluate(precision, [&](auto tag) {
    using NT = decltype(tag);
    if (!heights_overlap(NT(ha.base) + NT(a.sill), NT(a.height), NT(hb.base) + NT(b.sill),
                         NT(b.height)))
      return false;
    const LeafSweep<NT> la = leaf_sweep<NT>(ha, a, a.hinge, a.swing);
    const LeafSweep<NT> lb = leaf_sweep<NT>(hb, b, b.hinge, b.swing);
    if (is_surely(is_separated(la.square, lb.square, false))) return false;
    return discs_meet_in(la.hinge, la.radius2, lb.hinge, lb.radius2, clip(la.square, lb.square));
  });
}

bool clearance_hits_wall(const Scene& scene, const Opening& o, std::size_t host, std::size_t wall,
                         const RuleThresholds& t, Precision precision) {
  const Plan& plan = scene.plan();
  const Wall& h = plan.walls[host];
  const Wall& x = plan.walls[wall];
  return evaluate(precision, [&](auto tag) {
    using NT = decltype(tag);
    if (!heights_overlap(NT(h.base) + NT(o.sill), NT(kHeadroom), NT(x.base), NT(x.height)))
      return false;
    return interiors_overlap(
        clearance_rectangle<NT>(h, o, o.swing, t.clearance_width, t.clearance_depth),
        wall_polygon<NT>(plan, scene.joins(), wall));
  });
}

Box2 leaf_box(const Scene& scene, const Opening& o, std::size_t host) {
  CGAL::Protect_FPU_rounding<true> upward;
  return box_of(leaf_sweep<WrittenApprox>(scene.plan().walls[host], o, o.hinge, o.swing).square);
}

Box2 clearance_box(const Scene& scene, const Opening& o, std::size_t host,
                   const RuleThresholds& t) {
  CGAL::Protect_FPU_rounding<true> upward;
  return box_of(clearance_rectangle<WrittenApprox>(scene.plan().walls[host], o, o.swing,
                                                   t.clearance_width, t.clearance_depth));
}

std::vector<std::size_t> walls_hit_by_leaf(const Scene& scene, const Opening& o, std::size_t host,
                                           Precision precision) {
  std::vector<std::size_t> hit;
  for (const std::size_t w : scene.walls_near(leaf_box(scene, o, host)))
    if (w != host && leaf_hits_wall(scene, o, host, w, precision)) hit.push_back(w);
  return hit;
}

std::vector<std::size_t> walls_in_clearance(const Scene& scene, const Opening& o, std::size_t host,
                                            const RuleThresholds& t, Precision precision) {
  std::vector<std::size_t> hit;
  for (const std::size_t w : scene.walls_near(clearance_box(scene, o, host, t)))
    if (w != host && clearance_hits_wall(scene, o, host, w, t, precision)) hit.push_back(w);
  return hit;
}

bool is_narrower(double width, double min_width) {
  return decide_written([&](auto tag) {
    using NT = decltype(tag);
    return NT(width) < NT(min_width);
  });
}

}  // namespace roomcad::rules
