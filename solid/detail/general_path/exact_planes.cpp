// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/exact_planes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <optional>

#include <gmpxx.h>
#include <mpfr.h>
#include <tbb/concurrent_unordered_map.h>

#include "core/assert.h"
#include "core/flat_index.h"
#include "exact/interval_sign.h"

namespace roomcad::detail {
namespace {

// The coefficients (a, b, c, d) of a recipe, in T (Interval under upward rounding, or Exact).
template <class T>
std::array<T, 4> coefficients(const PlaneRecipe& r) {
  const auto& v = r.v;
  switch (r.kind) {
    case PlaneRecipe::Kind::axis: {
      std::array<T, 4> c{T(0), T(0), T(0), -(T(v[1]) + T(v[2]))};
      c[std::size_t(v[0])] = T(1);
      return c;
    }
    case PlaneRecipe::Kind::through2:
      return {T(v[3]) - T(v[1]), T(v[0]) - T(v[2]), T(0), T(v[1]) * T(v[2]) - T(v[0]) * T(v[3])};
    case PlaneRecipe::Kind::frame_line: {
      const T alpha(v[6]);
      const T origin = T(v[0]) * T(v[2]) + T(v[1]) * T(v[3]);
      return {alpha * T(v[2]), alpha * T(v[3]), T(v[7]), T(v[8]) - alpha * origin};
    }
    case PlaneRecipe::Kind::sloped_top: {
      const T ex = T(v[2]) - T(v[0]), ey = T(v[3]) - T(v[1]);
      const T k = T(v[5]) - T(v[6]), l2 = ex * ex + ey * ey;
      return {-(k * ex), -(k * ey), l2, k * (ex * T(v[0]) + ey * T(v[1])) - l2 * T(v[4])};
    }
    case PlaneRecipe::Kind::square_end: {
      const T a = T(v[2]) - T(v[0]), b = T(v[3]) - T(v[1]);
      return {a, b, T(0), -(a * T(v[4]) + b * T(v[5]))};
    }
    case PlaneRecipe::Kind::frame_edge: {
      const T u1 = T(v[4]) + T(v[6]) * T(v[5]), u2 = T(v[4]) + T(v[8]) * T(v[5]);
      const T z1 = T(v[10]) + T(v[7]) * T(v[11]), z2 = T(v[10]) + T(v[9]) * T(v[11]);
      const T du = u2 - u1, dz = z2 - z1;
      const T origin = T(v[0]) * T(v[2]) + T(v[1]) * T(v[3]) + u1;
      return {dz * T(v[2]), dz * T(v[3]), -du, du * z1 - dz * origin};
    }
  }
  return {T(0), T(0), T(0), T(0)};
}

template <class T>
T det2(const T& a, const T& b, const T& c, const T& d) {
  return a * d - b * c;
}

// det of the 3 x 3 matrix whose rows are (p[i], p[j], p[k]) of planes p0, p1, p2.
template <class T>
T det3(const std::array<T, 4>& p0, const std::array<T, 4>& p1, const std::array<T, 4>& p2,
       std::size_t i, std::size_t j, std::size_t k) {
  return p0[i] * det2(p1[j], p1[k], p2[j], p2[k]) - p0[j] * det2(p1[i], p1[k], p2[i], p2[k]) +
         p0[k] * det2(p1[i], p1[j], p2[i], p2[j]);
}

// det of the 4 x 4 matrix of rows p0..p3, by 2 x 2 minors of the first two and last two rows.
template <class T>
T det4(const std::array<T, 4>& a, const std::array<T, 4>& b, const std::array<T, 4>& c,
       const std::array<T, 4>& d) {
  const T s0 = det2(a[0], a[1], b[0], b[1]), s1 = det2(a[0], a[2], b[0], b[2]);
  const T s2 = det2(a[0], a[3], b[0], b[3]), s3 = det2(a[1], a[2], b[1], b[2]);
  const T s4 = det2(a[1], a[3], b[1], b[3]), s5 = det2(a[2], a[3], b[2], b[3]);
  const T c5 = det2(c[2], c[3], d[2], d[3]), c4 = det2(c[1], c[3], d[1], d[3]);
  const T c3 = det2(c[1], c[2], d[1], d[2]), c2 = det2(c[0], c[3], d[0], d[3]);
  const T c1 = det2(c[0], c[2], d[0], d[2]), c0 = det2(c[0], c[1], d[0], d[1]);
  return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

// Homogeneous coordinates of the meeting point of three planes (Cramer).
template <class T>
std::array<T, 4> meet(const std::array<T, 4>& p0, const std::array<T, 4>& p1,
                      const std::array<T, 4>& p2) {
  return {-det3(p0, p1, p2, 1, 2, 3), det3(p0, p1, p2, 0, 2, 3), -det3(p0, p1, p2, 0, 1, 3),
          det3(p0, p1, p2, 0, 1, 2)};
}

int exact_sign(const Exact& x) { return int(x.sign()); }

// The exact homogeneous coordinates of a point, from its planes in increasing order, so that
// every point of one representation gets the same numbers (another order may flip all four
// signs, which no predicate minds, but a table's value should not depend on who made it).
XHom exact_of_point(const PlaneSet& set, const XPoint& p) {
  if (p.is_explicit())
    return {Exact(p.approx[0].inf()), Exact(p.approx[1].inf()), Exact(p.approx[2].inf()), Exact(1)};
  auto ids = p.planes;
  std::sort(ids.begin(), ids.end());
  auto h = meet(set.exact(ids[0]), set.exact(ids[1]), set.exact(ids[2]));
  return {std::move(h[0]), std::move(h[1]), std::move(h[2]), std::move(h[3])};
}

// The correctly rounded double of num / den (ties to even). @pre den != 0.
double round_quotient(const Exact& num, const Exact& den) {
  // A close guess, then exact comparisons with the midpoints to its neighbours.
  double r = num.to_double() / den.to_double();
  if (std::isfinite(r) && r != 0.0) {
    const Exact n = den.sign() > 0 ? num : -num, d = den.sign() > 0 ? den : -den;
    for (int step = 0; step < 4; ++step) {
      const double up = std::nextafter(r, INFINITY), down = std::nextafter(r, -INFINITY);
      // 2 n vs (r + up) d: sums of two doubles are exact in Mpzf.
      const int above = exact_sign(Exact(2) * n - (Exact(r) + Exact(up)) * d);
      const int below = exact_sign(Exact(2) * n - (Exact(r) + Exact(down)) * d);
      if (above > 0) {
        r = up;
        continue;
      }
      if (below < 0) {
        r = down;
        continue;
      }
      const bool even = (std::bit_cast<std::uint64_t>(r) & 1u) == 0;
      if (above == 0 && !even) return up;
      if (below == 0 && !even) return down;
      return r;
    }
  }
  const mpq_class q = mpq_class(num) / mpq_class(den);
  mpfr_t m;
  mpfr_init2(m, 53);
  mpfr_set_q(m, q.get_mpq_t(), MPFR_RNDN);
  const double out = mpfr_get_d(m, MPFR_RNDN);
  mpfr_clear(m);
  return out;
}

}  // namespace

namespace {
thread_local bool t_upward = false;  // an IntervalScope rounds upward on this thread

// Sets the FPU to round upward for the scope, as Interval needs, unless an IntervalScope of
// this thread already did. Here, not in the header, so that the filters of the predicates
// below (millions of calls a build) inline it.
class UpwardRounding {
 public:
  UpwardRounding() : switched_(!t_upward) {
    if (switched_) saved_ = CGAL::FPU_get_and_set_cw(CGAL_FE_UPWARD);
  }
  ~UpwardRounding() {
    if (switched_) CGAL::FPU_set_cw(saved_);
  }
  UpwardRounding(const UpwardRounding&) = delete;
  UpwardRounding& operator=(const UpwardRounding&) = delete;

 private:
  bool switched_;
  CGAL::FPU_CW_t saved_{};
};
}  // namespace

IntervalScope::IntervalScope() : outer_(!t_upward) {
  if (!outer_) return;
  saved_ = CGAL::FPU_get_and_set_cw(CGAL_FE_UPWARD);
  t_upward = true;
}
IntervalScope::~IntervalScope() {
  if (!outer_) return;
  t_upward = false;
  CGAL::FPU_set_cw(saved_);
}

// The exact values of points by representation: TBB's concurrent map, whose lookups take no
// lock (threads look points up far more often than they add them); a value is made after the
// lookup (OnceSlot), so no thread waits on another's exact arithmetic.
class PlaneSet::PointTable {
 public:
  struct Entry {
    OnceSlot<XHom> hom;
    OnceSlot<std::array<double, 3>> rounded;
  };
  using Key = std::array<std::uint64_t, 3>;

  /// @return the entry of that representation, made empty on the first call. Thread-safe.
  Entry& entry(const Key& key) {
    if (const auto known = entries_.find(key); known != entries_.end()) return *known->second;
    return *entries_.emplace(key, std::make_unique<Entry>()).first->second;
  }

 private:
  tbb::concurrent_unordered_map<Key, std::unique_ptr<Entry>, BitsHash> entries_;
};

PlaneSet::PlaneSet() : points_(std::make_unique<PointTable>()) {}
PlaneSet::~PlaneSet() = default;
PlaneSet::PlaneSet(PlaneSet&&) noexcept = default;
PlaneSet& PlaneSet::operator=(PlaneSet&&) noexcept = default;

const XHom& PlaneSet::exact_point(const XPoint& p) const {
  return points_->entry(representation_key(p)).hom.get([&] { return exact_of_point(*this, p); });
}

PlaneId PlaneSet::add(const PlaneRecipe& recipe) {
  recipes_.push_back(recipe);
  {
    const UpwardRounding upward;
    approx_.push_back(coefficients<Interval>(recipe));
  }
  const bool simple = recipe.kind == PlaneRecipe::Kind::axis && recipe.v[2] == 0.0;
  axis_.emplace_back(simple ? int(recipe.v[0]) : -1, simple ? recipe.v[1] : 0.0);
  exact_.emplace_back();
  return PlaneId(recipes_.size() - 1);
}

PlaneId PlaneSet::add_axis(int axis, double value) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::axis;
  r.v[0] = axis, r.v[1] = value, r.v[2] = 0.0;
  return add(r);
}

const std::array<Exact, 4>& PlaneSet::exact(PlaneId id) const {
  return exact_[id].get([&] { return coefficients<Exact>(recipes_[id]); });
}

std::array<std::uint64_t, 3> representation_key(const XPoint& p) {
  if (p.is_explicit())  // + 0.0: -0.0 and 0.0 are one coordinate
    return {std::bit_cast<std::uint64_t>(p.approx[0].inf() + 0.0),
            std::bit_cast<std::uint64_t>(p.approx[1].inf() + 0.0),
            std::bit_cast<std::uint64_t>(p.approx[2].inf() + 0.0)};
  auto ids = p.planes;
  std::sort(ids.begin(), ids.end());
  // A NaN's bits last: an explicit point's coordinates are finite, so the kinds never meet.
  constexpr std::uint64_t kPlanesTag = 0x7FF4'0000'0000'B1E5ull;
  return {ids[0] | (std::uint64_t(ids[1]) << 32), ids[2], kPlanesTag};
}

XPoint make_point(double x, double y, double z) {
  RC_ASSERT(std::isfinite(x) && std::isfinite(y) && std::isfinite(z),
            "the general path's explicit points are finite (the plan validated)");
  XPoint p;
  p.approx = {Interval(x), Interval(y), Interval(z)};
  p.hom = {p.approx[0], p.approx[1], p.approx[2], Interval(1)};
  return p;
}

XPoint make_point(const PlaneSet& set, PlaneId a, PlaneId b, PlaneId c) {
  // Three axis planes at double offsets meet at an explicit point.
  const auto [aa, av] = simple_axis(set, a);
  const auto [ba, bv] = simple_axis(set, b);
  const auto [ca, cv] = simple_axis(set, c);
  if (aa >= 0 && ba >= 0 && ca >= 0 && aa != ba && ba != ca && aa != ca) {
    std::array<double, 3> xyz{};
    xyz[std::size_t(aa)] = av, xyz[std::size_t(ba)] = bv, xyz[std::size_t(ca)] = cv;
    return make_point(xyz[0], xyz[1], xyz[2]);
  }
  XPoint p;
  p.planes = {a, b, c};
  const UpwardRounding upward;
  RC_ASSERT(a != b && b != c && a != c, "a point is where three different planes meet");
  p.hom = meet(set.approx(a), set.approx(b), set.approx(c));
  RC_ASSERT(!(p.hom[3].inf() == 0 && p.hom[3].sup() == 0),
            "three planes that meet in a point have independent normals");
  for (std::size_t k = 0; k < 3; ++k) p.approx[k] = p.hom[k] / p.hom[3];
  // A coordinate fixed by an axis plane at a double is exact.
  for (const auto& [axis, value] : {std::pair{aa, av}, std::pair{ba, bv}, std::pair{ca, cv}})
    if (axis >= 0) p.approx[std::size_t(axis)] = Interval(value);
  return p;
}

namespace {

// The exact tails of the predicates below: out of line, so that their filters, which decide
// nearly every call, keep a small frame (Mpzf temporaries need a large one).
[[gnu::noinline]] int exact_side(const std::array<Exact, 4>& q, const XHom& h) {
  return exact_sign(q[0] * h.x + q[1] * h.y + q[2] * h.z + q[3] * h.w) * exact_sign(h.w);
}

const Exact& coordinate(const XHom& h, std::size_t k) { return k == 0 ? h.x : k == 1 ? h.y : h.z; }

[[gnu::noinline]] bool exact_same(const XHom& hp, const XHom& hq) {
  return hp.x * hq.w == hq.x * hp.w && hp.y * hq.w == hq.y * hp.w && hp.z * hq.w == hq.z * hp.w;
}

[[gnu::noinline]] int exact_compare(const XHom& hp, const XHom& hq, std::size_t k) {
  return exact_sign(coordinate(hp, k) * hq.w - coordinate(hq, k) * hp.w) * exact_sign(hp.w) *
         exact_sign(hq.w);
}

[[gnu::noinline]] int exact_compare(const XHom& h, double value, std::size_t k) {
  return exact_sign(coordinate(h, k) - Exact(value) * h.w) * exact_sign(h.w);
}

// The predicates on points, given how to get a point's exact homogeneous coordinates (computed
// only when the filters cannot decide).
template <class HomOf>
int side_of(const PlaneSet& set, PlaneRef plane, const XPoint& p, HomOf&& hom_of) {
  if (!p.is_explicit() && p.is_on_plane_by_definition(plane.id)) return 0;
  // Against an axis plane at a double, an exact coordinate decides at once.
  if (const auto [axis, value] = simple_axis(set, plane.id); axis >= 0) {
    const Interval& x = p.approx[std::size_t(axis)];
    if (x.inf() > value) return plane.sign;
    if (x.sup() < value) return -plane.sign;
    if (x.inf() == x.sup()) return 0;
  }
  {
    const UpwardRounding upward;
    const auto& q = set.approx(plane.id);
    const auto& h = p.hom;
    // q . (X, Y, Z, W) is the plane's value at the point times W.
    const int sq = interval_sign(q[0] * h[0] + q[1] * h[1] + q[2] * h[2] + q[3] * h[3]);
    const int sw = interval_sign(h[3]);
    if (sq != kUnknownSign && sw != kUnknownSign) return sq * sw * plane.sign;
  }
  return exact_side(set.exact(plane.id), hom_of()) * plane.sign;
}

template <class HomOf>
bool same_point(const XPoint& p, const XPoint& q, HomOf&& hom_of) {
  if (p.is_explicit() && q.is_explicit()) {
    for (std::size_t k = 0; k < 3; ++k)
      if (p.approx[k].inf() != q.approx[k].inf()) return false;
    return true;
  }
  bool all_points = true;
  for (std::size_t k = 0; k < 3; ++k) {
    if (!do_overlap(p.approx[k], q.approx[k])) return false;
    all_points = all_points && p.approx[k].inf() == p.approx[k].sup() &&
                 q.approx[k].inf() == q.approx[k].sup();
  }
  if (all_points) return true;  // overlapping point intervals: equal doubles
  if (!p.is_explicit() && !q.is_explicit()) {
    auto a = p.planes, b = q.planes;
    std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
    if (a == b) return true;
  }
  return exact_same(hom_of(0), hom_of(1));
}

template <class HomOf>
int compare_points(const XPoint& p, const XPoint& q, int axis, HomOf&& hom_of) {
  const auto k = std::size_t(axis);
  if (p.approx[k].sup() < q.approx[k].inf()) return -1;
  if (p.approx[k].inf() > q.approx[k].sup()) return 1;
  if (p.approx[k].inf() == p.approx[k].sup() && q.approx[k].inf() == q.approx[k].sup()) return 0;
  return exact_compare(hom_of(0), hom_of(1), k);
}

template <class HomOf>
int compare_value(const XPoint& p, double value, int axis, HomOf&& hom_of) {
  const auto k = std::size_t(axis);
  if (p.approx[k].sup() < value) return -1;
  if (p.approx[k].inf() > value) return 1;
  if (p.approx[k].inf() == p.approx[k].sup()) return 0;
  return exact_compare(hom_of(), value, k);
}

// The double nearest to hi + lo (ties to even) when lo is within half an ulp of hi, as
// two_sum leaves it; nothing otherwise. Every operation here is exact, so the rounding mode
// does not matter.
std::optional<double> nearest_to_sum(double hi, double lo) {
  if (lo == 0.0) return hi;
  if (!(std::abs(hi) >= 0x1p-1000 && std::abs(hi) <= 0x1p1000))
    return std::nullopt;  // normal, with room
  const double next = std::nextafter(hi, lo > 0.0 ? INFINITY : -INFINITY);
  const double half = (next - hi) / 2.0;  // half an ulp toward lo, signed (Sterbenz: exact)
  if (std::abs(lo) < std::abs(half)) return hi;
  if (lo == half) return (std::bit_cast<std::uint64_t>(hi) & 1u) == 0 ? hi : next;
  return std::nullopt;
}

// The coordinates of a point where three axis planes meet (an axis-aligned wall's faces at
// exact sums from its centre line, a storey's heights): each is its plane's sum of two
// doubles, rounded without exact arithmetic. Nothing for other points.
std::optional<std::array<double, 3>> round_axis_point(const PlaneSet& set, const XPoint& p) {
  if (p.is_explicit()) return std::nullopt;
  std::array<double, 3> out{};
  std::array<bool, 3> done{};
  for (const PlaneId id : p.planes) {
    const PlaneRecipe& r = set.recipe(id);
    if (r.kind != PlaneRecipe::Kind::axis) return std::nullopt;
    const auto axis = std::size_t(r.v[0]);
    const std::optional<double> x = nearest_to_sum(r.v[1], r.v[2]);
    if (done[axis] || !x) return std::nullopt;
    done[axis] = true;
    out[axis] = *x + 0.0;
  }
  return out;
}

// The point's coordinate k, rounded, where its other two are the doubles `known` (their
// intervals are points): from one of its planes with a non-zero coefficient a_k, x_k =
// -(d + sum of a_i x_i, i != k) / a_k, five exact operations on the plane's coefficients
// instead of the point's four exact 3 x 3 determinants (a slanted wall's side meeting a
// storey's height and a wall across it, the usual corner of a grid there). Nothing where no
// plane's interval tells a_k from 0.
std::optional<double> round_last_coordinate(const PlaneSet& set, const XPoint& p, std::size_t k,
                                            const std::array<double, 3>& known) {
  for (const PlaneId id : p.planes) {
    const Interval& a_k = set.approx(id)[k];
    if (a_k.inf() <= 0.0 && a_k.sup() >= 0.0) continue;
    const std::array<Exact, 4>& c = set.exact(id);
    Exact sum = c[3];
    for (std::size_t i = 0; i < 3; ++i)
      if (i != k) sum += c[i] * Exact(known[i]);
    return round_quotient(-sum, c[k]);
  }
  return std::nullopt;
}

std::array<double, 3> round_of(const PlaneSet& set, const XPoint& p) {
  std::array<double, 3> out{};
  int inexact = 0;
  std::size_t last = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    out[k] = p.approx[k].inf();
    if (p.approx[k].inf() != p.approx[k].sup()) ++inexact, last = k;
  }
  if (inexact == 0) return out;
  if (const auto axis_point = round_axis_point(set, p)) return *axis_point;
  if (inexact == 1 && !p.is_explicit())
    if (const auto x = round_last_coordinate(set, p, last, out)) {
      out[last] = *x + 0.0;
      return out;
    }
  return set.exact_rounding(p);
}

}  // namespace

const std::array<double, 3>& PlaneSet::exact_rounding(const XPoint& p) const {
  PointTable::Entry& e = points_->entry(representation_key(p));
  return e.rounded.get([&] {
    const XHom& h = e.hom.get([&] { return exact_of_point(*this, p); });
    std::array<double, 3> out{};
    for (std::size_t k = 0; k < 3; ++k) out[k] = round_quotient(coordinate(h, k), h.w) + 0.0;
    return out;
  });
}

// The free predicates look a point's exact coordinates up in the set only where a filter fails.
int side(const PlaneSet& set, PlaneRef plane, const XPoint& p) {
  return side_of(set, plane, p, [&]() -> const XHom& { return set.exact_point(p); });
}

bool is_same_point(const PlaneSet& set, const XPoint& p, const XPoint& q) {
  return same_point(p, q, [&](int i) -> const XHom& { return set.exact_point(i == 0 ? p : q); });
}

int compare_coordinate(const PlaneSet& set, const XPoint& p, const XPoint& q, int axis) {
  return compare_points(p, q, axis,
                        [&](int i) -> const XHom& { return set.exact_point(i == 0 ? p : q); });
}

int compare_coordinate(const PlaneSet& set, const XPoint& p, double value, int axis) {
  return compare_value(p, value, axis, [&]() -> const XHom& { return set.exact_point(p); });
}

std::array<double, 3> round_point(const PlaneSet& set, const XPoint& p) { return round_of(set, p); }

std::size_t PointCache::add(const XPoint& p) {
  points_.push_back(p);
  exact_.emplace_back();
  return points_.size() - 1;
}

const XHom& PointCache::exact(std::size_t i) {
  const XHom* h = exact_[i].load(std::memory_order_acquire);
  if (h == nullptr) {  // threads that race store the same pointer
    h = &set_.exact_point(points_[i]);
    exact_[i].store(h, std::memory_order_release);
  }
  return *h;
}

int PointCache::side(PlaneRef plane, std::size_t i) {
  return side_of(set_, plane, points_[i], [&]() -> const XHom& { return exact(i); });
}

bool PointCache::is_same(std::size_t i, std::size_t j) {
  if (i == j) return true;
  return same_point(points_[i], points_[j],
                    [&](int k) -> const XHom& { return exact(k == 0 ? i : j); });
}

int PointCache::compare(std::size_t i, std::size_t j, int axis) {
  if (i == j) return 0;
  return compare_points(points_[i], points_[j], axis,
                        [&](int k) -> const XHom& { return exact(k == 0 ? i : j); });
}

int PointCache::compare(std::size_t i, double value, int axis) {
  return compare_value(points_[i], value, axis, [&]() -> const XHom& { return exact(i); });
}

std::array<double, 3> PointCache::round(std::size_t i) { return round_of(set_, points_[i]); }

int orient_normals(const PlaneSet& set, PlaneRef a, PlaneRef b, PlaneRef c) {
  int s = kUnknownSign;
  {
    const UpwardRounding upward;
    s = interval_sign(det3(set.approx(a.id), set.approx(b.id), set.approx(c.id), 0, 1, 2));
  }
  if (s == kUnknownSign)
    s = exact_sign(det3(set.exact(a.id), set.exact(b.id), set.exact(c.id), 0, 1, 2));
  return s * a.sign * b.sign * c.sign;
}

int dot_normals(const PlaneSet& set, PlaneRef a, PlaneRef b) {
  int s = kUnknownSign;
  {
    const UpwardRounding upward;
    const auto& p = set.approx(a.id);
    const auto& q = set.approx(b.id);
    s = interval_sign(p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  }
  if (s == kUnknownSign) {
    const auto& p = set.exact(a.id);
    const auto& q = set.exact(b.id);
    s = exact_sign(p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  }
  return s * a.sign * b.sign;
}

int dot_in_plane(const PlaneSet& set, PlaneRef plane, PlaneRef a, PlaneRef b) {
  // (n_a . n_b)(n . n) - (n_a . n)(n_b . n): the dot product of n x n_a and n x n_b.
  auto value = [&](const auto& n, const auto& p, const auto& q) {
    auto dot = [](const auto& x, const auto& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    return dot(p, q) * dot(n, n) - dot(p, n) * dot(q, n);
  };
  int s = kUnknownSign;
  {
    const UpwardRounding upward;
    s = interval_sign(value(set.approx(plane.id), set.approx(a.id), set.approx(b.id)));
  }
  if (s == kUnknownSign)
    s = exact_sign(value(set.exact(plane.id), set.exact(a.id), set.exact(b.id)));
  return s * a.sign * b.sign;
}

}  // namespace roomcad::detail
