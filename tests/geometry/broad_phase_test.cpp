// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace roomcad {
namespace {

bool meet(const SpaceBox& a, const SpaceBox& b) {
  return !(a.plan.max_x < b.plan.min_x || b.plan.max_x < a.plan.min_x ||
           a.plan.max_y < b.plan.min_y || b.plan.max_y < a.plan.min_y || a.max_z < b.min_z ||
           b.max_z < a.min_z);
}

// Boxes on a coarse grid, so that many touch exactly (closed boxes meet there).
std::vector<SpaceBox> random_boxes(std::mt19937& random, std::size_t n) {
  std::uniform_int_distribution<int> at(0, 20), size(0, 4);
  std::vector<SpaceBox> boxes;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = at(random), y = at(random), z = at(random) / 4.0;
    boxes.push_back(
        {{x, y, x + size(random), y + size(random), 3 * k + 1}, z, z + size(random) / 4.0});
  }
  return boxes;
}

// The pairs of boxes that meet, by testing every pair: (lower index, higher), sorted (the
// indices grow with the position).
IndexPairs all_meeting(const std::vector<SpaceBox>& boxes) {
  IndexPairs pairs;
  for (std::size_t a = 0; a < boxes.size(); ++a)
    for (std::size_t b = a + 1; b < boxes.size(); ++b)
      if (meet(boxes[a], boxes[b])) pairs.emplace_back(boxes[a].plan.index, boxes[b].plan.index);
  return pairs;
}

// The pairs (left, right) of boxes that meet, by testing every pair, sorted.
IndexPairs all_meeting(const std::vector<SpaceBox>& left, const std::vector<SpaceBox>& right) {
  IndexPairs pairs;
  for (const SpaceBox& a : left)
    for (const SpaceBox& b : right)
      if (meet(a, b)) pairs.emplace_back(a.plan.index, b.plan.index);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

TEST(BroadPhase, SpaceBoxesMeetWhereTheirPlansAndHeightsBothMeetAsABruteForceSaysSorted) {
  std::mt19937 random(7);
  const std::vector<SpaceBox> boxes = random_boxes(random, 300);
  const IndexPairs expected = all_meeting(boxes);
  ASSERT_GT(expected.size(), 100u);
  EXPECT_EQ(find_meeting_boxes(boxes), expected);
  // In plan alone, storeys stand on one another: more pairs (the brute force's, with every
  // box at one height).
  std::vector<Box2> plans;
  std::vector<SpaceBox> flat;
  for (const SpaceBox& b : boxes) plans.push_back(b.plan), flat.push_back({b.plan, 0.0, 0.0});
  const IndexPairs in_plan = all_meeting(flat);
  EXPECT_EQ(find_meeting_boxes(plans), in_plan);
  EXPECT_GT(in_plan.size(), expected.size());
}

TEST(BroadPhase, PairsOfTwoSequencesOfSpaceBoxesComeInLeftRightOrder) {
  std::mt19937 random(11);
  const std::vector<SpaceBox> left = random_boxes(random, 120), right = random_boxes(random, 80);
  const IndexPairs expected = all_meeting(left, right);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(find_meeting_boxes(left, right), expected);
}

TEST(BroadPhase, ManyBoxesGoToTheSegmentTreeAndMeetAsABruteForceSays) {
  // 3000 boxes: past the 2048 below which a sweep finds the pairs (the tests above), CGAL's
  // segment tree does, alone and against a second sequence.
  std::mt19937 random(13);
  std::vector<SpaceBox> boxes = random_boxes(random, 3000);
  for (SpaceBox& b : boxes) b.plan.min_x *= 8.0, b.plan.max_x *= 8.0;  // fewer pairs, still many
  const IndexPairs expected = all_meeting(boxes);
  ASSERT_GT(expected.size(), 3000u);
  EXPECT_EQ(find_meeting_boxes(boxes), expected);
  const std::vector<SpaceBox> left(boxes.begin(), boxes.begin() + 2000),
      right(boxes.begin() + 2000, boxes.end());
  const IndexPairs across = all_meeting(left, right);
  ASSERT_FALSE(across.empty());
  EXPECT_EQ(find_meeting_boxes(left, right), across);
}

TEST(BroadPhase, AStoreyMeetsTheOneItStandsOnAtItsFloorAndNotTheOneAboveThat) {
  const Box2 plan{0.0, 0.0, 4.0, 0.2, 0};
  std::vector<SpaceBox> storeys;
  for (std::size_t k = 0; k < 3; ++k) {
    Box2 p = plan;
    p.index = k;
    storeys.push_back({p, 2.5 * double(k), 2.5 * double(k + 1)});
  }
  EXPECT_EQ(find_meeting_boxes(storeys), (IndexPairs{{0, 1}, {1, 2}}));
}

TEST(BroadPhase, ASpaceBoxHoldsEveryHeightBetweenItsEndsInEitherOrder) {
  const Box2 plan{0.0, 0.0, 1.0, 1.0, 3};
  const double base = 0.1, top = 0.1 + 0.2;  // the sum rounds: the box must hold it all
  const SpaceBox up = space_box(plan, base, top), down = space_box(plan, top, base);
  EXPECT_LT(up.min_z, base);
  EXPECT_GT(up.max_z, top);
  EXPECT_EQ(up.min_z, down.min_z);
  EXPECT_EQ(up.max_z, down.max_z);
  EXPECT_EQ(up.plan.index, 3u);
  const double most = std::numeric_limits<double>::max();
  const SpaceBox unbounded = space_box(plan, 0.0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(unbounded.min_z, -most);
  EXPECT_EQ(unbounded.max_z, most);
  const SpaceBox huge = space_box(plan, -most, most);
  EXPECT_EQ(huge.min_z, -most);
  EXPECT_EQ(huge.max_z, most);
}

}  // namespace
}  // namespace roomcad
