// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/box_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace roomcad {
namespace {

/// A box as low x, low y, high x, high y.
using Bounds = std::array<double, 4>;

/// @return the boxes, each tagged with its position.
std::vector<Box2> tagged(const std::vector<Bounds>& bounds) {
  std::vector<Box2> boxes;
  for (const Bounds& b : bounds) boxes.push_back({b[0], b[1], b[2], b[3], boxes.size()});
  return boxes;
}

Box2 box(const Bounds& b) { return {b[0], b[1], b[2], b[3], 0}; }

/// @return the boxes k that `grid` visits for `query`, sorted; fails the test if one is visited
/// twice. Fails the test where find, which any thread may call, disagrees with for_each_meeting.
std::vector<std::size_t> visited(BoxGrid& grid, const Bounds& query) {
  std::vector<std::size_t> found;
  grid.for_each_meeting(box(query), [&](std::size_t k) { found.push_back(k); });
  std::sort(found.begin(), found.end());
  EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << "a box visited twice";
  EXPECT_EQ(grid.find(box(query)), found);
  return found;
}

std::vector<std::size_t> meeting(const std::vector<Bounds>& boxes, const Bounds& query) {
  std::vector<std::size_t> found;
  for (std::size_t k = 0; k < boxes.size(); ++k)
    if (boxes_meet(box(query), box(boxes[k]))) found.push_back(k);
  return found;
}

TEST(BoxGrid, VisitsExactlyTheBoxesThatMeetTheQueryOnce) {
  // Boxes of every size, touching ones (closed boxes meet at a shared edge), and the bounds an
  // exact point's interval can have: infinite, NaN, and low above high.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> at(-10.0, 10.0), size(0.0, 3.0);
  std::vector<Bounds> boxes;
  for (int k = 0; k < 400; ++k) {
    const double x = at(random), y = at(random);
    boxes.push_back({x, y, x + size(random) * size(random), y + size(random)});
  }
  boxes.push_back({1.0, 1.0, 2.0, 2.0});
  boxes.push_back({2.0, 0.0, 3.0, 1.0});  // meets the one before at its corner
  boxes.push_back({-INFINITY, 0.0, 0.5, 0.5});
  boxes.push_back({0.0, 0.0, INFINITY, INFINITY});
  boxes.push_back({NAN, 0.0, 1.0, 1.0});
  boxes.push_back({5.0, 5.0, 4.0, 6.0});  // low above high
  BoxGrid grid(tagged(boxes));
  std::vector<Bounds> queries = {
      {2.0, 2.0, 2.0, 2.0}, {-1e300, -1e300, 1e300, 1e300},
      {NAN, 0, 0, 0},       {100.0, 100.0, 101.0, 101.0},
      {4.5, 5.5, 4.5, 5.5}, {3.9, 5.5, 5.1, 5.5}};  // meets the box whose low is above its high
  for (int k = 0; k < 300; ++k) {
    const double x = at(random), y = at(random);
    queries.push_back({x, y, x + size(random), y + size(random) / 10});
  }
  for (const Bounds& q : queries)
    EXPECT_EQ(visited(grid, q), meeting(boxes, q)) << q[0] << " " << q[1];
}

TEST(BoxGrid, BoxesDrawnOverOneAnotherAreAllFound) {
  // 3,000 boxes over one another and a few small ones: filed cell by cell, each would fill
  // the grid's 55 x 55 cells; the grid falls back to one cell and still finds exactly them.
  std::vector<Bounds> boxes(3000, Bounds{0.0, 0.0, 10.0, 10.0});
  for (int k = 0; k < 10; ++k) boxes.push_back({k * 1.0, k * 1.0, k + 0.5, k + 0.5});
  BoxGrid grid(tagged(boxes));
  for (const Bounds& q :
       {Bounds{3.6, 3.6, 3.7, 3.7}, Bounds{2.0, 2.0, 2.1, 2.1}, Bounds{20, 20, 21, 21}})
    EXPECT_EQ(visited(grid, q), meeting(boxes, q));
}

TEST(BoxGrid, NoBoxesAndBoxesAtOnePoint) {
  BoxGrid empty;
  EXPECT_TRUE(visited(empty, {0, 0, 1, 1}).empty());
  const std::vector<Bounds> points(5, Bounds{3.0, 3.0, 3.0, 3.0});
  BoxGrid same(tagged(points));
  EXPECT_EQ(visited(same, {3.0, 3.0, 3.0, 3.0}).size(), 5u);
  EXPECT_TRUE(visited(same, {3.5, 3.0, 4.0, 3.0}).empty());
}

}  // namespace
}  // namespace roomcad
