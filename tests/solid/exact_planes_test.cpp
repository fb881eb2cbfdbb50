// SPDX-License-Identifier: GPL-3.0-or-later
// The plane-based exact kernel of the general path (detail/exact_planes.h), checked against
// rational arithmetic (GMP) written out independently here.
#include "solid/detail/general_path/exact_planes.h"

#include <fmt/format.h>
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

namespace roomcad {
namespace {

using detail::PlaneId;
using detail::PlaneRecipe;
using detail::PlaneRef;
using detail::PlaneSet;
using detail::XPoint;

using Q = mpq_class;
using QPlane = std::array<Q, 4>;
using QPoint = std::array<Q, 3>;

// A vertical plane through (px, py) -> (qx, qy), its right outside, in rationals.
QPlane through(double px, double py, double qx, double qy) {
  const Q a = Q(qy) - Q(py), b = Q(px) - Q(qx);
  return {a, b, Q(0), Q(-(a * Q(px) + b * Q(py)))};
}

PlaneId add_through(PlaneSet& set, double px, double py, double qx, double qy) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::through2;
  r.v[0] = px, r.v[1] = py, r.v[2] = qx, r.v[3] = qy;
  return set.add(r);
}

// The point where three planes meet (Cramer), in rationals.
QPoint meet(const QPlane& p, const QPlane& q, const QPlane& r) {
  auto det3 = [](const Q& a, const Q& b, const Q& c, const Q& d, const Q& e, const Q& f, const Q& g,
                 const Q& h, const Q& i) -> Q {
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  };
  const Q w = det3(p[0], p[1], p[2], q[0], q[1], q[2], r[0], r[1], r[2]);
  return {det3(-p[3], p[1], p[2], -q[3], q[1], q[2], -r[3], r[1], r[2]) / w,
          det3(p[0], -p[3], p[2], q[0], -q[3], q[2], r[0], -r[3], r[2]) / w,
          det3(p[0], p[1], -p[3], q[0], q[1], -q[3], r[0], r[1], -r[3]) / w};
}

int sign_at(const QPlane& p, const QPoint& x) {
  return sgn(Q(p[0] * x[0] + p[1] * x[1] + p[2] * x[2] + p[3]));
}

TEST(ExactPlanes, SideOfAThreePlanePointMatchesRationals) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-20.0, 20.0);
  PlaneSet set;
  int zeros = 0;
  for (int trial = 0; trial < 300; ++trial) {
    double c[8];
    for (double& v : c) v = coord(rng);
    // Two vertical planes and a horizontal one meet at a point; a fourth plane passes exactly
    // through it every third time (through the point's plan position and another point).
    const QPlane p = through(c[0], c[1], c[2], c[3]), q = through(c[4], c[5], c[6], c[7]);
    const double z = coord(rng);
    const QPlane h{0, 0, 1, -Q(z)};
    const QPoint x = meet(p, q, h);
    const PlaneId pi = add_through(set, c[0], c[1], c[2], c[3]),
                  qi = add_through(set, c[4], c[5], c[6], c[7]);
    const PlaneId hi = set.add_axis(2, z);
    const XPoint point = detail::make_point(set, pi, qi, hi);
    double r0 = coord(rng), r1 = coord(rng), r2 = coord(rng), r3 = coord(rng);
    if (trial % 3 == 0)
      r0 = c[0], r1 = c[1], r2 = c[2], r3 = c[3];  // plane p itself, by another id
    const QPlane t = through(r0, r1, r2, r3);
    const PlaneId ti = add_through(set, r0, r1, r2, r3);
    const int expected = sign_at(t, x);
    zeros += expected == 0;
    EXPECT_EQ(detail::side(set, {ti, 1}, point), expected) << trial;
    EXPECT_EQ(detail::side(set, {ti, -1}, point), -expected) << trial;
  }
  EXPECT_GE(zeros, 100);  // the degenerate case, where only exact arithmetic can answer
}

TEST(ExactPlanes, EqualPointsOfDifferentPlanesAreTheSame) {
  PlaneSet set;
  // x = 1 and y = 2 meet z = 3 at (1, 2, 3); so do the diagonal x - y = -1 (through (0, 1)
  // and (3, 4)) and y = 2.
  const PlaneId x1 = set.add_axis(0, 1.0), y2 = set.add_axis(1, 2.0), z3 = set.add_axis(2, 3.0);
  const PlaneId diagonal = add_through(set, 0.0, 1.0, 3.0, 4.0);
  const XPoint a = detail::make_point(set, x1, y2, z3);
  const XPoint b = detail::make_point(set, diagonal, y2, z3);
  EXPECT_TRUE(a.is_explicit());
  EXPECT_FALSE(b.is_explicit());
  EXPECT_TRUE(detail::is_same_point(set, a, b));
  EXPECT_EQ(detail::compare_coordinate(set, a, b, 0), 0);
  EXPECT_EQ(detail::side(set, {diagonal, 1}, a), 0);
  const XPoint c = detail::make_point(set, diagonal, set.add_axis(1, 2.5), z3);
  EXPECT_FALSE(detail::is_same_point(set, a, c));
  EXPECT_EQ(detail::compare_coordinate(set, a, c, 0), -1);
}

TEST(ExactPlanes, RoundingIsToTheNearestDouble) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-1e3, 1e3);
  PlaneSet set;
  for (int trial = 0; trial < 200; ++trial) {
    double c[8];
    for (double& v : c) v = coord(rng);
    const PlaneId pi = add_through(set, c[0], c[1], c[2], c[3]),
                  qi = add_through(set, c[4], c[5], c[6], c[7]);
    const double z = coord(rng);
    const XPoint point = detail::make_point(set, pi, qi, set.add_axis(2, z));
    const QPoint x =
        meet(through(c[0], c[1], c[2], c[3]), through(c[4], c[5], c[6], c[7]), {0, 0, 1, -Q(z)});
    const auto rounded = detail::round_point(set, point);
    for (std::size_t k = 0; k < 3; ++k) {
      // No double lies strictly closer to the exact coordinate than the rounded one.
      const Q err = abs(Q(x[k] - Q(rounded[k])));
      EXPECT_LE(err, Q(abs(Q(x[k] - Q(std::nextafter(rounded[k], INFINITY)))))) << trial;
      EXPECT_LE(err, Q(abs(Q(x[k] - Q(std::nextafter(rounded[k], -INFINITY)))))) << trial;
    }
  }
}

TEST(ExactPlanes, APointsExactValuesAreMadeOnceForItsThreePlanesInAnyOrderOnAnyThread) {
  PlaneSet set;
  const PlaneId a = add_through(set, 0.1, 0.2, 3.3, 1.7), b = add_through(set, -2.9, 0.4, 0.7, 5.1);
  const PlaneId c = set.add_axis(2, 0.3);
  const XPoint p = detail::make_point(set, a, b, c), q = detail::make_point(set, c, a, b);
  const XPoint other = detail::make_point(set, b, c, set.add_axis(0, 1.0));
  // One representation, one table entry; the rounding is round_point's (which reads it).
  const detail::XHom* first = &set.exact_point(p);
  EXPECT_EQ(&set.exact_point(q), first);
  EXPECT_NE(&set.exact_point(other), first);
  EXPECT_EQ(set.exact_rounding(q), detail::round_point(set, p));
  // Threads asking for fresh points all at once get one entry each.
  std::vector<XPoint> fresh;
  for (int k = 0; k < 64; ++k)
    fresh.push_back(detail::make_point(set, a, b, set.add_axis(2, 0.5 + k)));
  std::vector<const detail::XHom*> seen(fresh.size() * 8);
  tbb::parallel_for(std::size_t{0}, seen.size(),
                    [&](std::size_t i) { seen[i] = &set.exact_point(fresh[i % fresh.size()]); });
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i], seen[i % fresh.size()]);
    EXPECT_EQ(set.exact_rounding(fresh[i % fresh.size()])[2], 0.5 + double(i % fresh.size()));
  }
}

// An axis plane x[axis] = hi + lo (an axis-aligned wall's face at an exact sum).
PlaneId add_axis_sum(PlaneSet& set, int axis, double hi, double lo) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::axis;
  r.v[0] = axis, r.v[1] = hi, r.v[2] = lo;
  return set.add(r);
}

// No double lies closer to x than r, and of two as close r is the even one.
void expect_nearest_ties_to_even(const Q& x, double r, const std::string& what) {
  const Q err = abs(Q(x - Q(r)));
  const Q up = abs(Q(x - Q(std::nextafter(r, INFINITY)))),
          down = abs(Q(x - Q(std::nextafter(r, -INFINITY))));
  EXPECT_LE(err, up) << what;
  EXPECT_LE(err, down) << what;
  if (err == up || err == down) {  // a tie
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r) & 1u, 0u) << what;
  }
}

TEST(ExactPlanes, CornersOfAxisPlanesAtSumsRoundToTheNearestDoubleTiesToEven) {
  // Each coordinate is hi + lo with |lo| at most half an ulp of hi, ties included: below a
  // power of two the ulp is half as large. Checked against the exact sum's nearest double,
  // ties to even, worked out in rationals.
  const double u = 0x1p-52;  // ulp of 1
  const std::array<std::pair<double, double>, 8> sums{
      {{1.0, u / 2},            // tie: 1 is even
       {1.0 + u, u / 2},        // tie: up to even
       {1.0, -u / 4},           // tie below 2^0
       {1.0 + u, -u / 2},       // tie: down to even
       {4.1, 0x1p-53 * 0.3},    // not a tie
       {-3.9, -0x1p-52 * 0.7},  // not a tie, negative
       {2.0, -u / 2 * 0.99},    // just short of a tie
       {0.1, 1e-18}}};
  PlaneSet set;
  for (const auto& [hi, lo] : sums) {
    const XPoint point =
        detail::make_point(set, add_axis_sum(set, 0, hi, lo), add_axis_sum(set, 1, -hi, -lo),
                           add_axis_sum(set, 2, hi, 0.0));
    const auto rounded = detail::round_point(set, point);
    const std::array<Q, 3> exact{Q(Q(hi) + Q(lo)), Q(-(Q(hi) + Q(lo))), Q(hi)};
    for (std::size_t k = 0; k < 3; ++k)
      expect_nearest_ties_to_even(exact[k], rounded[k], fmt::format("{} + {} axis {}", hi, lo, k));
  }
}

// A slanted wall's side meeting two axis planes: two coordinates are the axis planes' doubles,
// the third is rounded from the slanted plane alone (round_last_coordinate), and must be what
// the point's full exact coordinates give, ties included.
TEST(ExactPlanes, CornersWithOneInexactCoordinateRoundLikeTheirExactCoordinates) {
  const double u = 0x1p-52;
  PlaneSet set;
  // y = 3 x at x = 1 + u: y = 3 + 3u, halfway between 3 + 2u and 3 + 4u (the even one).
  const PlaneId steep = add_through(set, 0.0, 0.0, 1.0, 3.0);
  const XPoint tie =
      detail::make_point(set, steep, set.add_axis(0, 1.0 + u), set.add_axis(2, 0.25));
  EXPECT_EQ(detail::round_point(set, tie)[1], 3.0 + 4 * u);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> coord(-1e3, 1e3);
  for (int trial = 0; trial < 300; ++trial) {
    double c[6];
    for (double& v : c) v = coord(rng);
    const QPlane slanted = through(c[0], c[1], c[2], c[3]);
    // Across x (trials even) or y (odd): the point's other plan coordinate is the inexact one.
    const int across = trial % 2;
    const PlaneId t = add_through(set, c[0], c[1], c[2], c[3]);
    const XPoint point =
        detail::make_point(set, t, set.add_axis(across, c[4]), set.add_axis(2, c[5]));
    QPlane axis{0, 0, 0, -Q(c[4])};
    axis[std::size_t(across)] = 1;
    const QPoint x = meet(slanted, axis, {0, 0, 1, -Q(c[5])});
    const auto rounded = detail::round_point(set, point);
    EXPECT_EQ(rounded, set.exact_rounding(point)) << trial;
    for (std::size_t k = 0; k < 3; ++k)
      expect_nearest_ties_to_even(x[k], rounded[k], fmt::format("trial {} axis {}", trial, k));
  }
}

TEST(ExactPlanes, EqualPlanesFromDifferentPointsAreGrouped) {
  PlaneSet set;
  // One line through (0, 0.1) and (3, 0.4), given by three different pairs of its points,
  // once reversed; and a plane a hair off it.
  const PlaneId a = add_through(set, 0.0, 0.1, 3.0, 0.4);
  const PlaneId b = add_through(set, 1.0, 0.2, 2.0, 0.30000000000000004);  // 0.1 + 0.2 as read
  const PlaneId c = add_through(set, 3.0, 0.4, 0.0, 0.1);
  const PlaneId d = add_through(set, 0.0, 0.1, 3.0, std::nextafter(0.4, 1.0));
  const std::vector<PlaneRef> groups = set.find_equal_planes();
  EXPECT_EQ(groups[c].id, a);
  EXPECT_EQ(groups[c].sign, -1);
  EXPECT_EQ(groups[d].id, d);
  // b is the same plane exactly when both its points lie on the line, as rationals decide.
  const QPlane line = through(0.0, 0.1, 3.0, 0.4);
  const bool on_line =
      sign_at(line, {1.0, 0.2, 0}) == 0 && sign_at(line, {2.0, 0.30000000000000004, 0}) == 0;
  EXPECT_EQ(groups[b].id == a, on_line);
}

TEST(ExactPlanes, NormalsTurnAsTheirDeterminant) {
  PlaneSet set;
  const PlaneId x = set.add_axis(0, 0.0), y = set.add_axis(1, 0.0), z = set.add_axis(2, 0.0);
  EXPECT_EQ(detail::orient_normals(set, {x, 1}, {y, 1}, {z, 1}), 1);
  EXPECT_EQ(detail::orient_normals(set, {y, 1}, {x, 1}, {z, 1}), -1);
  EXPECT_EQ(detail::orient_normals(set, {x, 1}, {x, -1}, {z, 1}), 0);
  EXPECT_EQ(detail::dot_in_plane(set, {z, 1}, {x, 1}, {x, 1}), 1);
  EXPECT_EQ(detail::dot_in_plane(set, {z, 1}, {x, 1}, {y, 1}), 0);
}

}  // namespace
}  // namespace roomcad
