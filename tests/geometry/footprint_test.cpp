// SPDX-License-Identifier: GPL-3.0-or-later
// wall_footprint's shortcuts, for axis-aligned walls (sums of doubles rounded, ties down) and
// for skewed ones (128-bit intervals that tell the nearest double), give bit for bit what the
// exact construction (exact::wall_corners in Radical, rounded by exact::round_to_nearest)
// gives: a mitre's shared corner must not depend on which way each of its two walls was
// computed.
#include <gtest/gtest.h>

#include <random>

#include "geometry/exact_wall_lines.h"
#include "geometry/joins.h"
#include "support/model_support.h"

namespace roomcad {
namespace {

std::array<Point2, 4> exact_corners(const Plan& plan, const Joins& joins, std::size_t wall) {
  const exact::Exact::Scope scope;
  const auto corners = exact::wall_corners<exact::Exact>(plan, joins, wall);
  std::array<Point2, 4> out;
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = {exact::round_to_nearest(corners[i].x), exact::round_to_nearest(corners[i].y)};
  return out;
}

void expect_exact_footprints(const Plan& plan) {
  const Joins joins = find_joins(plan);
  for (std::size_t w = 0; w < plan.walls.size(); ++w) {
    const auto fast = wall_footprint(plan, joins, w), exact = exact_corners(plan, joins, w);
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(fast[i].x, exact[i].x) << "wall " << w << " corner " << i;
      EXPECT_EQ(fast[i].y, exact[i].y) << "wall " << w << " corner " << i;
    }
  }
}

TEST(Footprint, AxisAlignedCornersAreTheExactOnesRounded) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> milli(-20000, 20000);
  std::uniform_int_distribution<int> thick(10, 400);
  auto decimal = [&] { return milli(rng) / 1000.0; };  // "3.285" as read: not exact in binary
  for (int trial = 0; trial < 100; ++trial) {
    Plan plan = test::empty_plan();
    // An L of two mitred walls, and a straight run of two, in random places and thicknesses.
    const Point2 a{decimal(), decimal()}, b{decimal(), a.y}, c{b.x, decimal()};
    if (a.x == b.x || b.y == c.y) continue;
    test::add_wall(plan, "ab", a, b).thickness = thick(rng) / 1000.0;
    test::add_wall(plan, "bc", b, c).thickness = thick(rng) / 1000.0;
    const Point2 d{decimal(), decimal()}, e{d.x, decimal()}, f{d.x, decimal()};
    if (d.y != e.y && e.y != f.y && (e.y - d.y) * (f.y - e.y) > 0) {
      test::add_wall(plan, "de", d, e).thickness = 0.2;
      test::add_wall(plan, "ef", e, f).thickness = 0.2;
    }
    expect_exact_footprints(plan);
  }
}

TEST(Footprint, TiesRoundDownAsTheExactPathDoes) {
  // -1.17 - 0.13 lies exactly halfway between two doubles (a real home's wall: Studio's wall2).
  Plan plan = test::empty_plan();
  test::add_wall(plan, "a", {4.105, -1.17}, {7.4, -1.17}).thickness = 0.26;
  test::add_wall(plan, "b", {7.4, -1.17}, {7.4, -4.5}).thickness = 0.26;
  expect_exact_footprints(plan);
  EXPECT_EQ(wall_footprint(plan, find_joins(plan), 0)[0].y, -1.3);
}

TEST(Footprint, SkewedCornersAreTheExactOnesRounded) {
  // Chains of walls at random angles (the chords of an arc, a bay window), mitred at every
  // node: every corner involves the square roots of two walls' squared lengths.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> milli(-20000, 20000);
  std::uniform_int_distribution<int> thick(10, 400);
  auto decimal = [&] { return milli(rng) / 1000.0; };
  for (int trial = 0; trial < 100; ++trial) {
    Plan plan = test::empty_plan();
    Point2 from{decimal(), decimal()};
    for (int k = 0; k < 4; ++k) {
      const Point2 to{decimal(), decimal()};
      const char* const names[] = {"w0", "w1", "w2", "w3"};
      test::add_wall(plan, names[k], from, to).thickness = thick(rng) / 1000.0;
      from = to;
    }
    expect_exact_footprints(plan);
  }
}

}  // namespace
}  // namespace roomcad
