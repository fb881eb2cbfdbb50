// SPDX-License-Identifier: GPL-3.0-or-later
// Plane-based exact geometry for the general build path (general_solid.h).
//
// Every face of the solid lies on a plane of some primitive (a wall piece, a hole), and every
// vertex is where three such planes meet. So points are kept as plane triples ("TPI": three-
// plane intersection) or, where they are input data, as explicit doubles; nothing is ever
// rounded until the mesh is written. Planes are defined from the plan's doubles by recipes
// whose coefficients are polynomials in those doubles (no division), so they are exact in
// CGAL::Mpzf (exact +, -, x on binary floats). Every predicate is the sign of a polynomial
// in plane coefficients: the side of a plane a point lies on is sign(det4) * sign(det3) of
// the coefficient matrices (Cramer), the turn between two lines of a plane is sign(det3) of
// the normals. Each is evaluated first in interval arithmetic and, only when the interval
// holds 0 (the shapes touch, or nearly), exactly in Mpzf. Where a plane is one of a point's
// own three, the answer (0) is known without arithmetic.
//
// Why not CGAL's Epeck: its lazy numbers build a DAG per operation and fall back to
// rationals with gcds; a constructed point's exact value cost ~50 us there against ~3 us
// for an Mpzf determinant here, and touching shapes (the normal case in a plan) need exact
// answers all the time.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include "solid/detail/general_path/once_slot.h"

namespace roomcad::detail {

using Interval = CGAL::Interval_nt<false>;  ///< needs upward rounding (IntervalScope)
using Exact = CGAL::Mpzf;
using PlaneId = std::uint32_t;

/// Rounds upward for the whole scope on this thread, so that the predicates below need not
/// switch the rounding mode each time (a measurable share of their cost in the inner loops).
/// Inside it, plain double arithmetic rounds upward too: only approximations (bounds,
/// guesses that exact arithmetic checks) may be computed there. Mpzf and MPFR do not depend
/// on the FPU's mode.
class IntervalScope {
 public:
  IntervalScope();
  ~IntervalScope();
  IntervalScope(const IntervalScope&) = delete;
  IntervalScope& operator=(const IntervalScope&) = delete;

 private:
  bool outer_;
  CGAL::FPU_CW_t saved_{};
};

/// How a plane's coefficients (a, b, c, d: a x + b y + c z + d = 0) come from doubles.
struct PlaneRecipe {
  enum class Kind : std::uint8_t {
    axis,        ///< x[v0] = v1 + v2 (an exact sum: a double-double), normal +e[v0]
    through2,    ///< vertical, through plan points (v0, v1) -> (v2, v3); its right is outside
    frame_line,  ///< v6 * u + v7 * z + v8 = 0, u = (p - (v0, v1)) . (v2, v3) (a wall's frame)
    sloped_top,  ///< z = v4 + (v5 - v6) * u / L^2, u = (p - from) . (to - from), from (v0, v1),
                 ///< to (v2, v3), L = |to - from|; z above is outside
    frame_edge,  ///< in a wall's frame (from (v0, v1), dir (v2, v3)), the line through
                 ///< (U(v6), Z(v7)) and (U(v8), Z(v9)), U(s) = v4 + s * v5, Z(t) = v10 + t * v11;
                 ///< its right (seen from +normal, walking the edge) is outside
    square_end,  ///< vertical, through the plan point (v4, v5) square to the line from (v0, v1)
                 ///< to (v2, v3): normal (v2 - v0, v3 - v1), exactly, whose side is outside
  };
  Kind kind = Kind::axis;
  std::array<double, 12> v{};
};

/// A plane of a PlaneSet, oriented: `sign` -1 flips it. Its negative side is "inside".
struct PlaneRef {
  PlaneId id = 0;
  int sign = 1;
  friend bool operator==(const PlaneRef&, const PlaneRef&) = default;
};

/// A point: explicit doubles (planes[0] == kExplicit), or the meeting point of three planes.
struct XPoint {
  static constexpr PlaneId kExplicit = UINT32_MAX;
  std::array<PlaneId, 3> planes{kExplicit, kExplicit, kExplicit};
  std::array<Interval, 3> approx;  ///< encloses the exact coordinates (points if exact doubles)
  std::array<Interval, 4> hom;     ///< encloses homogeneous coordinates (X, Y, Z, W): x = X / W
  [[nodiscard]] bool is_explicit() const { return planes[0] == kExplicit; }
  /// @return whether plane `id` is one of the three that define the point. O(1).
  [[nodiscard]] bool is_on_plane_by_definition(PlaneId id) const {
    return planes[0] == id || planes[1] == id || planes[2] == id;
  }
};

/// Exact homogeneous coordinates (X / W, Y / W, Z / W).
struct XHom {
  Exact x, y, z, w;
};

/// The planes of one build, with their interval and (lazily) exact coefficients, and the exact
/// values of the points the predicates needed them for, each point's computed once: a vertex
/// lies on three planes and is met in each of their 2D booleans, in the sections crossing
/// them and in stitching, on any thread.
/// Adding is single-threaded; reading (every predicate) may run on many threads.
class PlaneSet {
 public:
  PlaneSet();
  ~PlaneSet();
  PlaneSet(PlaneSet&&) noexcept;
  PlaneSet& operator=(PlaneSet&&) noexcept;

  /// Adds a plane. @return its id. O(1).
  PlaneId add(const PlaneRecipe& recipe);
  /// @return an axis plane x[axis] = value (normal +e[axis]).
  PlaneId add_axis(int axis, double value);
  [[nodiscard]] std::size_t size() const { return recipes_.size(); }
  [[nodiscard]] const std::array<Interval, 4>& approx(PlaneId id) const { return approx_[id]; }
  /// @return the exact coefficients (computed once, thread-safe).
  [[nodiscard]] const std::array<Exact, 4>& exact(PlaneId id) const;
  [[nodiscard]] const PlaneRecipe& recipe(PlaneId id) const { return recipes_[id]; }
  /// @return {axis, offset} if the plane is x[axis] = offset with offset a double, else {-1, 0}.
  [[nodiscard]] std::pair<int, double> simple_axis(PlaneId id) const { return axis_[id]; }

  /// Groups equal planes (exactly: proportional coefficients).
  /// @return per plane, its group's first plane and the orientation relative to it.
  ///         O(n log n) plus exact tests between planes whose invariants overlap.
  [[nodiscard]] std::vector<PlaneRef> find_equal_planes() const;

  /// @return the point's exact homogeneous coordinates, computed on the first call for its
  ///         representation (representation_key) and kept: thread-safe. O(1) after the first.
  [[nodiscard]] const XHom& exact_point(const XPoint& p) const;
  /// @return the point's coordinates rounded to the nearest doubles, from exact_point, computed
  ///         once per representation. (round_point decides most points without it.)
  [[nodiscard]] const std::array<double, 3>& exact_rounding(const XPoint& p) const;

 private:
  class PointTable;
  std::vector<PlaneRecipe> recipes_;
  std::vector<std::array<Interval, 4>> approx_;
  std::vector<std::pair<int, double>> axis_;
  std::deque<OnceSlot<std::array<Exact, 4>>> exact_;  // a deque: adding keeps the slots in place
  std::unique_ptr<PointTable> points_;
};

/// @return a key equal for two points of the same representation: the same explicit doubles,
///         or the same three planes in any order. (Equal points of different representations
///         have different keys: only an exact test finds those.) O(1).
[[nodiscard]] std::array<std::uint64_t, 3> representation_key(const XPoint& p);

/// @return the explicit point (x, y, z). @pre finite.
[[nodiscard]] XPoint make_point(double x, double y, double z);
/// @return the point where planes a, b, c meet. @pre their normals are independent.
[[nodiscard]] XPoint make_point(const PlaneSet& set, PlaneId a, PlaneId b, PlaneId c);

/// @return the side of the oriented plane the point lies on: -1 inside, 0 on it, +1 outside.
[[nodiscard]] int side(const PlaneSet& set, PlaneRef plane, const XPoint& p);
/// @return whether two points are the same point.
[[nodiscard]] bool is_same_point(const PlaneSet& set, const XPoint& p, const XPoint& q);
/// @return sign(p[axis] - q[axis]).
[[nodiscard]] int compare_coordinate(const PlaneSet& set, const XPoint& p, const XPoint& q,
                                     int axis);
/// @return sign(p[axis] - value).
[[nodiscard]] int compare_coordinate(const PlaneSet& set, const XPoint& p, double value, int axis);
/// @return sign(det(n_a, n_b, n_c)) of the oriented normals.
[[nodiscard]] int orient_normals(const PlaneSet& set, PlaneRef a, PlaneRef b, PlaneRef c);
/// @return sign of the dot product of the directions of a and b within `plane` (their normals
///         with the part along the plane's normal removed): > 0 when two lines of the plane
///         that share their trace have their negative sides on the same side.
[[nodiscard]] int dot_in_plane(const PlaneSet& set, PlaneRef plane, PlaneRef a, PlaneRef b);
/// @return sign of the dot product of two oriented normals.
[[nodiscard]] int dot_normals(const PlaneSet& set, PlaneRef a, PlaneRef b);
/// @return whether two planes are the same set of points (either orientation).
[[nodiscard]] bool are_same_plane(const PlaneSet& set, PlaneId a, PlaneId b);
/// @return the point's coordinates, each rounded to the nearest double (ties to even).
[[nodiscard]] std::array<double, 3> round_point(const PlaneSet& set, const XPoint& p);
/// Points of one computation, for the predicates of exact_planes.h by point index; each
/// point keeps a pointer to its exact homogeneous coordinates (PlaneSet::exact_point) once it
/// needed them, so that a point tested again skips the set's table. Adding is single-threaded;
/// the predicates may run on many threads.
class PointCache {
 public:
  explicit PointCache(const PlaneSet& set) : set_(set) {}
  /// Adds a point (equal points are not merged). @return its index.
  std::size_t add(const XPoint& p);
  [[nodiscard]] const XPoint& operator[](std::size_t i) const { return points_[i]; }
  [[nodiscard]] std::size_t size() const { return points_.size(); }
  [[nodiscard]] const PlaneSet& planes() const { return set_; }
  [[nodiscard]] int side(PlaneRef plane, std::size_t i);
  [[nodiscard]] bool is_same(std::size_t i, std::size_t j);
  [[nodiscard]] int compare(std::size_t i, std::size_t j, int axis);
  [[nodiscard]] int compare(std::size_t i, double value, int axis);
  [[nodiscard]] std::array<double, 3> round(std::size_t i);

 private:
  const XHom& exact(std::size_t i);
  const PlaneSet& set_;
  std::vector<XPoint> points_;
  std::deque<std::atomic<const XHom*>> exact_;  // a deque: adding keeps the slots in place
};

/// @return {axis, offset} if the plane is x[axis] = offset with offset a double, else {-1, 0}.
[[nodiscard]] inline std::pair<int, double> simple_axis(const PlaneSet& set, PlaneId id) {
  return set.simple_axis(id);
}

/// @return whether two intervals share a point. O(1).
[[nodiscard]] inline bool do_overlap(const Interval& a, const Interval& b) {
  return !(a.sup() < b.inf() || b.sup() < a.inf());
}

/// @return a double interval enclosing coordinate `axis` of the point.
[[nodiscard]] inline std::pair<double, double> bounds(const XPoint& p, int axis) {
  return {p.approx[std::size_t(axis)].inf(), p.approx[std::size_t(axis)].sup()};
}

}  // namespace roomcad::detail
