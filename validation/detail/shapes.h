// SPDX-License-Identifier: GPL-3.0-or-later
// Exact shape tests for validation: mitred wall footprints, opening holes, and whether two
// convex quadrilaterals share interior area, in any number type (see modeling's
// exact::decide). Includes CGAL: only wall_checks.cpp and opening_checks.cpp include it.
#pragma once

#include <array>
#include <optional>
#include <type_traits>
#include <vector>

#include "geometry/broad_phase.h"
#include "geometry/exact_wall_lines.h"
#include "validation/report.h"

namespace roomcad::detail {

template <class NT>
using Quad = std::array<exact::Pt<NT>, 4>;

/// Interval footprints of the usable walls, computed once, and their outward-rounded boxes.
/// A footprint whose intervals cannot be formed (a near-parallel mitre) is left empty and
/// built exactly on demand.
class Footprints {
 public:
  Footprints(const Plan& plan, const Joins& joins, const std::vector<bool>& usable);

  /// @return wall w's mitred footprint in NT (cached for intervals).
  template <class NT>
  Quad<NT> get(std::size_t w) const {
    if constexpr (std::is_same_v<NT, exact::Approx>) {
      if (approx_[w]) return *approx_[w];
      throw CGAL::Uncertain_conversion_exception("footprint needs exact arithmetic");
    } else {
      return exact::wall_corners<NT>(plan_, joins_, w);
    }
  }
  /// Boxes (index = wall) of the usable walls' footprints.
  [[nodiscard]] const std::vector<Box2>& boxes() const { return boxes_; }

 private:
  const Plan& plan_;
  const Joins& joins_;
  std::vector<std::optional<Quad<exact::Approx>>> approx_;
  std::vector<Box2> boxes_;
};

/// @return the outward-rounded box of a quad given in intervals.
Box2 box_of(const Quad<exact::Approx>& q, std::size_t index);

/// The hole of an opening in the plane: its span along the host's centre line, through the
/// full thickness: {start-right, end-right, end-left, start-left} (counter-clockwise).
template <class NT>
Quad<NT> hole_corners(const Wall& w, const Opening& o) {
  const exact::WallLine<NT> line = exact::wall_line<NT>(w);
  const exact::Pt<NT> d = line.to - line.from;
  const NT length = exact::root(exact::dot(d, d));
  const exact::Pt<NT> start = line.from + (NT(o.offset) / length) * d;
  const exact::Pt<NT> end = line.from + ((NT(o.offset) + NT(o.width)) / length) * d;
  return {start - line.half_normal, end - line.half_normal, end + line.half_normal,
          start + line.half_normal};
}

/// @return true if the open intervals (lo1, hi1) and (lo2, hi2) meet.
template <class NT>
auto spans_overlap(const NT& lo1, const NT& hi1, const NT& lo2, const NT& hi2) {
  return lo1 < hi2 && lo2 < hi1;
}

/// @return a fixed point near p: p itself, or for intervals the point of its lower bounds
/// (exact), so that differences from it carry no extra width.
template <class NT>
exact::Pt<NT> anchor_at(const exact::Pt<NT>& p) {
  if constexpr (std::is_same_v<NT, exact::Approx>) return {NT(p.x.inf()), NT(p.y.inf())};
  else return p;
}

/// @return whether every one of `low` is at most every one of `high`.
template <class NT>
bool all_at_or_below(const std::array<NT, 4>& low, const std::array<NT, 4>& high) {
  for (const NT& a : low)
    for (const NT& b : high)
      if (!(a <= b)) return false;
  return true;
}

/// @return true if `axis` separates p and q (their projections meet at most at a point).
/// Projections are taken from an anchor on p: the axis is uncertain in intervals, and
/// multiplying it by coordinates a million metres from the origin would magnify that.
/// Intervals compare the hulls of the projections. The finer types compare each corner of p
/// with each corner of q: along the normal of one of its own edges two corners of a quad
/// project to the same value, and taking the extremes would compare those two, a tie that
/// only Radical decides; a corner of p ties with one of q only where the quads touch.
template <class NT>
bool separates(const exact::Pt<NT>& axis, const Quad<NT>& p, const Quad<NT>& q) {
  const exact::Pt<NT> o = anchor_at(p[0]);
  const auto along = [&](const Quad<NT>& s) {
    const auto at = [&](std::size_t i) { return exact::dot(axis, s[i] - o); };
    return std::array<NT, 4>{at(0), at(1), at(2), at(3)};
  };
  const std::array<NT, 4> along_p = along(p), along_q = along(q);
  if constexpr (std::is_same_v<NT, exact::Approx>) {
    NT p_lo = along_p[0], p_hi = p_lo, q_lo = along_q[0], q_hi = q_lo;
    for (std::size_t i = 1; i < 4; ++i) {
      p_lo = CGAL::min(p_lo, along_p[i]), p_hi = CGAL::max(p_hi, along_p[i]);
      q_lo = CGAL::min(q_lo, along_q[i]), q_hi = CGAL::max(q_hi, along_q[i]);
    }
    return p_hi <= q_lo || q_hi <= p_lo;
  } else {
    return all_at_or_below(along_p, along_q) || all_at_or_below(along_q, along_p);
  }
}

/// @return true if convex quads p and q share interior area (touching is not sharing).
/// Separating-axis test on the edge normals of both; zero-length edges give no axis.
template <class NT>
bool interiors_overlap(const Quad<NT>& p, const Quad<NT>& q) {
  for (const Quad<NT>* shape : {&p, &q})
    for (std::size_t i = 0; i < 4; ++i) {
      const exact::Pt<NT> edge = (*shape)[(i + 1) % 4] - (*shape)[i];
      if (edge.x == NT(0) && edge.y == NT(0)) continue;
      if (separates(exact::Pt<NT>{-edge.y, edge.x}, p, q)) return false;
    }
  return true;
}

/// @return wall w's mitred footprint in doubles (not exactly rounded): for messages, where
///         the exact construction would cost more and say nothing more.
std::array<Point2, 4> approximate_footprint(const Plan& plan, const Joins& joins, std::size_t w);

/// @return how far p and q overlap: the least distance one must move to clear the other,
///         along the returned unit direction (pointing from p to q). Doubles; for messages.
std::pair<double, Point2> penetration(const std::array<Point2, 4>& p,
                                      const std::array<Point2, 4>& q);

/// Twice the signed area of `polygon` clipped to the convex counter-clockwise `quad`
/// (Sutherland-Hodgman: exact for any simple polygon against a convex window).
template <class NT>
NT clipped_area(const Polygon& polygon, const Quad<NT>& quad) {
  std::vector<exact::Pt<NT>> ring;
  for (const Point2& p : polygon) ring.push_back(exact::to_pt<NT>(p));
  for (std::size_t e = 0; e < 4 && !ring.empty(); ++e) {
    const exact::Pt<NT> a = quad[e], d = quad[(e + 1) % 4] - quad[e];
    std::vector<exact::Pt<NT>> out;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const exact::Pt<NT>& p = ring[k];
      const exact::Pt<NT>& q = ring[(k + 1) % ring.size()];
      const NT sp = exact::cross(d, p - a), sq = exact::cross(d, q - a);  // >= 0: inside
      if (sp >= NT(0)) out.push_back(p);
      if ((sp < NT(0) && sq > NT(0)) || (sp > NT(0) && sq < NT(0)))
        out.push_back(p + (sp / (sp - sq)) * (q - p));
    }
    ring = std::move(out);
  }
  NT twice(0);
  for (std::size_t k = 0; k < ring.size(); ++k)
    twice = twice + exact::cross(ring[k], ring[(k + 1) % ring.size()]);
  return twice;
}

/// @return the box of a polygon (of at least one corner), with the caller's index. O(n).
Box2 box_of_polygon(const Polygon& p, std::size_t index);

struct Usable;
struct ResolvedPlan;

/// opening_outside_wall and opening_overlap on the usable openings of `plan` (on their walls'
/// polylines, under their sloped tops, by their outlines); opening_blocked on `resolved`'s
/// pieces by other walls (opening_checks.cpp).
void check_openings(const Plan& plan, const Usable& usable, const ResolvedPlan& resolved,
                    const Joins& joins, const Footprints& footprints, Report& report);

/// obstruction_overlap: an obstruction sharing interior volume with a wall or a slab
/// (obstruction_checks.cpp).
void check_obstructions(const Usable& usable, const ResolvedPlan& resolved,
                        const Footprints& footprints, Report& report);

/// slab_overlap, opening_blocked by slabs, out_of_bounds of slabs and levels, and
/// invalid_value for slab outlines and holes that are not simple or not nested (slab_checks.cpp).
void check_slabs(const Plan& plan, const Usable& usable, const ResolvedPlan& resolved,
                 const Joins& joins, const Footprints& footprints, Report& report);

}  // namespace roomcad::detail
