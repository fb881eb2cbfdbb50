// SPDX-License-Identifier: GPL-3.0-or-later
// Convex polygons in any of the rule number types (written_number.h): clipping, closest
// points, squared distances and the overlap tests the rules decide with. Every function is
// a template over NT so that decide_written evaluates it first in intervals, then exactly;
// comparisons on intervals throw when they cannot decide, which sends the whole predicate to
// exact arithmetic. Nothing here takes a square root: distances are compared squared.
#pragma once

#include <array>
#include <cstddef>

#include "core/assert.h"
#include "validation/rules/written_number.h"

// Truths combine with | and & on purpose, never || and &&: for intervals they are
// CGAL::Uncertain<bool>, decided only when both sides are, with no branch on an undecided
// value; clang warns on the exact (bool) instantiation.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wbitwise-instead-of-logical"
#endif

namespace roomcad::rules {

template <class NT>
using Pt = exact::Pt<NT>;

/// A convex polygon, counter-clockwise, of at most 16 corners (a wall piece clipped by a
/// square has at most 10). Corners may repeat where a clip passes through one.
template <class NT>
struct Poly {
  std::array<Pt<NT>, 16> v;
  std::size_t n = 0;
  void push(const Pt<NT>& p) {
    RC_ASSERT(n < v.size(), "a convex clip of small polygons has few corners");
    v[n++] = p;
  }
  [[nodiscard]] const Pt<NT>& operator[](std::size_t i) const { return v[i]; }
  [[nodiscard]] const Pt<NT>& next(std::size_t i) const { return v[(i + 1) % n]; }
};

/// @return the polygon with these corners (counter-clockwise).
template <class NT, std::size_t N>
Poly<NT> make_poly(const std::array<Pt<NT>, N>& corners) {
  Poly<NT> p;
  for (const Pt<NT>& c : corners) p.push(c);
  return p;
}

/// @return the part of p on the left of the directed line a -> b (boundary included).
template <class NT>
Poly<NT> clip_left(const Poly<NT>& p, const Pt<NT>& a, const Pt<NT>& b) {
  Poly<NT> out;
  const Pt<NT> d = b - a;
  for (std::size_t i = 0; i < p.n; ++i) {
    const Pt<NT>& cur = p[i];
    const Pt<NT>& nxt = p.next(i);
    const NT sc = exact::cross(d, cur - a);
    const NT sn = exact::cross(d, nxt - a);
    const bool keep = sc >= NT(0);
    if (keep) out.push(cur);
    if ((sc > NT(0) && sn < NT(0)) || (!keep && sn > NT(0)))
      out.push(cur + (sc / (sc - sn)) * (nxt - cur));
  }
  return out;
}

/// @return p intersected with the convex polygon `clipper` (counter-clockwise).
template <class NT>
Poly<NT> clip(const Poly<NT>& p, const Poly<NT>& clipper) {
  Poly<NT> out = p;
  for (std::size_t i = 0; i < clipper.n && out.n > 0; ++i)
    out = clip_left(out, clipper[i], clipper.next(i));
  return out;
}

/// @return true if the convex polygon encloses a positive area.
template <class NT>
bool has_interior(const Poly<NT>& p) {
  if (p.n < 3) return false;
  NT twice_area(0);
  for (std::size_t i = 1; i + 1 < p.n; ++i)
    twice_area = twice_area + exact::cross(p[i] - p[0], p[i + 1] - p[0]);
  return twice_area > NT(0);
}

/// @return the point of the closed segment a-b nearest to q.
template <class NT>
Pt<NT> closest_on_segment(const Pt<NT>& q, const Pt<NT>& a, const Pt<NT>& b) {
  const Pt<NT> d = b - a;
  const NT t = exact::dot(q - a, d);
  if (t <= NT(0)) return a;
  const NT len2 = exact::dot(d, d);
  if (t >= len2) return b;
  return a + (t / len2) * d;
}

template <class NT>
NT squared_distance(const Pt<NT>& a, const Pt<NT>& b) {
  const Pt<NT> d = a - b;
  return exact::dot(d, d);
}

/// @return true if q lies in the closed convex polygon p.
template <class NT>
bool is_inside(const Pt<NT>& q, const Poly<NT>& p) {
  for (std::size_t i = 0; i < p.n; ++i)
    if (exact::cross(p.next(i) - p[i], q - p[i]) < NT(0)) return false;
  return true;
}

/// @return the point of the closed convex polygon p (n >= 1) nearest to q.
template <class NT>
Pt<NT> closest_point(const Pt<NT>& q, const Poly<NT>& p) {
  if (p.n >= 3 && is_inside(q, p)) return q;
  Pt<NT> best = p[0];
  NT best_d2 = squared_distance(q, best);
  for (std::size_t i = 0; i < p.n; ++i) {
    const Pt<NT> c = closest_on_segment(q, p[i], p.next(i));
    const NT d2 = squared_distance(q, c);
    if (d2 < best_d2) best = c, best_d2 = d2;
  }
  return best;
}

/// @return whether q is nearer than sqrt(r2) to the closed segment a-b, as a truth that is
///         uncertain only near the boundary: no branch on intermediate values (closest-point
///         branches compare equal distances at a shared corner, which intervals cannot decide).
template <class NT>
Truth<NT> is_nearer_than(const Pt<NT>& q, const Pt<NT>& a, const Pt<NT>& b, const NT& r2) {
  const Pt<NT> d = b - a;
  const NT c = exact::cross(d, q - a);
  return (squared_distance(q, a) < r2) |
         ((exact::dot(q - a, d) > NT(0)) & (exact::dot(q - b, d) < NT(0)) &
          (c * c < r2 * exact::dot(d, d)));
}

/// @return whether q is nearer than sqrt(r2) to the closed convex polygon p (n >= 1): inside
///         it, or near one of its edges. O(p.n).
template <class NT>
Truth<NT> is_nearer_than(const Pt<NT>& q, const Poly<NT>& p, const NT& r2) {
  Truth<NT> inside = p.n >= 3;
  Truth<NT> near = false;
  for (std::size_t i = 0; i < p.n; ++i) {
    inside = inside & (exact::cross(p.next(i) - p[i], q - p[i]) >= NT(0));
    near = near | is_nearer_than(q, p[i], p.next(i), r2);
    if (is_surely(near)) return near;
  }
  return inside | near;
}

/// @return whether the line through a with normal `axis` has p and q on its two sides:
/// strictly (`strict`, the closed sets do not meet) or weakly (the interiors do not meet).
template <class NT>
Truth<NT> separates(const Pt<NT>& axis, const Poly<NT>& p, const Poly<NT>& q, bool strict) {
  const Pt<NT> o = p[0];
  NT p_lo(0), p_hi(0);
  for (std::size_t i = 1; i < p.n; ++i) {
    const NT t = exact::dot(axis, p[i] - o);
    p_lo = lesser(p_lo, t), p_hi = greater(p_hi, t);
  }
  NT q_lo = exact::dot(axis, q[0] - o), q_hi = q_lo;
  for (std::size_t i = 1; i < q.n; ++i) {
    const NT t = exact::dot(axis, q[i] - o);
    q_lo = lesser(q_lo, t), q_hi = greater(q_hi, t);
  }
  if (strict) return (p_hi < q_lo) | (q_hi < p_lo);
  return (p_hi <= q_lo) | (q_hi <= p_lo);
}

/// Separating-axis test on the edge normals of both (zero-length edges give no axis). An
/// axis that separates for sure decides even when the intervals cannot tell about others.
template <class NT>
Truth<NT> is_separated(const Poly<NT>& p, const Poly<NT>& q, bool strict) {
  Truth<NT> out = false;
  for (const Poly<NT>* shape : {&p, &q})
    for (std::size_t i = 0; i < shape->n; ++i) {
      const Pt<NT> e = shape->next(i) - (*shape)[i];
      // An edge along an axis has one coordinate near 0: decide on both at once.
      if (is_surely((e.x == NT(0)) & (e.y == NT(0)))) continue;
      out = out | separates(Pt<NT>{-e.y, e.x}, p, q, strict);
      if (is_surely(out)) return out;
    }
  return out;
}

/// @return true if the interiors of convex polygons p and q meet (touching is not meeting).
template <class NT>
bool interiors_overlap(const Poly<NT>& p, const Poly<NT>& q) {
  return has_interior(p) && has_interior(q) && !static_cast<bool>(is_separated(p, q, false));
}

/// @return true if the closed convex polygons p and q (n >= 1 each) are closer than sqrt(w2):
///         they meet, or a corner of one is nearer than that to an edge of the other.
template <class NT>
bool is_closer_than(const Poly<NT>& p, const Poly<NT>& q, const NT& w2) {
  if (p.n == 0 || q.n == 0) return false;
  Truth<NT> closer = false;
  for (const auto& [a, b] : {std::pair{&p, &q}, std::pair{&q, &p}})
    for (std::size_t i = 0; i < a->n; ++i)
      for (std::size_t j = 0; j < b->n; ++j) {
        closer = closer |
                 (squared_distance((*a)[i], closest_on_segment((*a)[i], (*b)[j], b->next(j))) < w2);
        if (is_surely(closer)) return true;
      }
  return static_cast<bool>(closer | !is_separated(p, q, true));
}

/// @return true if the open disc about h with squared radius r2 meets the interior of the
///         convex polygon k. O(k.n).
template <class NT>
bool disc_meets_interior(const Pt<NT>& h, const NT& r2, const Poly<NT>& k) {
  return has_interior(k) && static_cast<bool>(is_nearer_than(h, k, r2));
}

/// @return true if the open discs (h1, r1^2) and (h2, r2^2) and the interior of convex k have
///         a common point. The convex function g = max(|p-h1|^2 - r1^2, |p-h2|^2 - r2^2) is
///         least over k at the point of k nearest h1, nearest h2, or nearest h1 on the line
///         where the two terms are equal; the discs meet inside k iff g < 0 there.
template <class NT>
bool discs_meet_in(const Pt<NT>& h1, const NT& r1, const Pt<NT>& h2, const NT& r2,
                   const Poly<NT>& k) {
  if (!has_interior(k)) return false;
  const auto g_below_zero = [&](const Pt<NT>& p) {
    return squared_distance(p, h1) < r1 && squared_distance(p, h2) < r2;
  };
  if (g_below_zero(closest_point(h1, k)) || g_below_zero(closest_point(h2, k))) return true;
  const Pt<NT> d = h2 - h1;
  const NT d2 = exact::dot(d, d);
  if (d2 == NT(0)) return false;  // concentric: the two candidates above decide
  // The radical line: p0 + t * perp(d), p0 nearest h1 on it; clip t to k.
  const Pt<NT> p0 = h1 + ((d2 + r1 - r2) / (NT(2) * d2)) * d;
  const Pt<NT> dir{-d.y, d.x};
  bool has_lo = false, has_hi = false;
  NT lo(0), hi(0);
  for (std::size_t i = 0; i < k.n; ++i) {
    const Pt<NT> e = k.next(i) - k[i];
    const NT s0 = exact::cross(e, p0 - k[i]);  // >= 0 inside
    const NT s1 = exact::cross(e, dir);        // change per unit t
    if (s1 == NT(0)) {
      if (s0 < NT(0)) return false;
      continue;
    }
    const NT t = -s0 / s1;
    if (s1 > NT(0)) {
      if (!has_lo || t > lo) lo = t, has_lo = true;
    } else if (!has_hi || t < hi) {
      hi = t, has_hi = true;
    }
  }
  if (has_lo && has_hi && hi < lo) return false;
  NT t(0);
  if (has_lo && t < lo) t = lo;
  if (has_hi && t > hi) t = hi;
  return g_below_zero(p0 + t * dir);
}

}  // namespace roomcad::rules

#if defined(__clang__)
#pragma clang diagnostic pop
#endif
