// SPDX-License-Identifier: GPL-3.0-or-later
// Edits of the version-2 objects and fields: levels and slabs added, set, moved and removed;
// version-2 fields set from text and cleared.
#include <gtest/gtest.h>

#include "plan/plan_edit.h"
#include "plan/plan_fields.h"

namespace roomcad {
namespace {

/// A level "up" holding wall "w" (with door "d") and slab "floor".
Plan storey_plan() {
  Plan plan;
  plan.levels.push_back(Level{.id = "up", .elevation = 3.0, .height = 2.6});
  Wall w;
  w.id = "w";
  w.level = "up";
  w.from = {0, 0};
  w.to = {4, 0};
  plan.walls.push_back(w);
  Opening d = default_opening(OpeningType::door);
  d.id = "d";
  d.wall = "w";
  d.offset = 1;
  plan.openings.push_back(d);
  plan.slabs.push_back(
      Slab{.id = "floor", .level = "up", .outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}}});
  return plan;
}

Code code_of(auto edit) {
  Plan unused;
  const Result<EditSummary> made = make_edit([&](Plan&) { return edit(); }, unused);
  return made.ok() ? Code::internal : made.code();
}

TEST(PlanEditV2, Version2FieldsAreSetFromTextAndClearedByNone) {
  Plan plan = storey_plan();
  EXPECT_EQ(set_field(plan, "w", "height_at_end", "1.2")->changed, std::vector<std::string>{"w"});
  EXPECT_EQ(plan.walls[0].height_at_end, 1.2);
  ASSERT_TRUE(set_field(plan, "w", "height_at_end", "none").ok());
  EXPECT_EQ(plan.walls[0].height_at_end, std::nullopt);
  ASSERT_TRUE(set_field(plan, "d", "shape", "0,0;1,0;1,0.7;0.5,1;0,0.7").ok());
  EXPECT_EQ(plan.openings[0].shape.size(), 5u);
  EXPECT_EQ(plan.openings[0].shape[3], (Point2{0.5, 1}));
  ASSERT_TRUE(set_field(plan, "floor", "holes", "1,1;2,1;2,2;1,2|3,1;3.5,1;3.5,2").ok());
  ASSERT_EQ(plan.slabs[0].holes.size(), 2u);
  EXPECT_EQ(plan.slabs[0].holes[1].size(), 3u);
  EXPECT_EQ(code_of([&] { return set_field(plan, "w", "arc_extent", "round"); }),
            Code::usage_error);
  EXPECT_EQ(code_of([&] { return set_field(plan, "floor", "outline", "1,1;2"); }),
            Code::usage_error);
  EXPECT_EQ(code_of([&] { return set_field(plan, "w", "from", "none"); }), Code::usage_error);
}

TEST(PlanEditV2, RenamingALevelRenamesItsWallsAndSlabsReferences) {
  Plan plan = storey_plan();
  const EditSummary s = set_field(plan, "up", "id", "first").value();
  EXPECT_EQ(s.changed, (std::vector<std::string>{"first", "w", "floor"}));
  EXPECT_EQ(plan.walls[0].level, "first");
  EXPECT_EQ(plan.slabs[0].level, "first");
}

TEST(PlanEditV2, ALevelWithObjectsIsRemovedOnlyWithCascade) {
  Plan plan = storey_plan();
  EXPECT_EQ(dependent_objects(plan, "up"), (std::vector<std::string>{"w", "d", "floor"}));
  EXPECT_EQ(code_of([&] { return remove_object(plan, "up"); }), Code::edit_refused);
  EXPECT_EQ(plan.levels.size(), 1u);
  const EditSummary s = remove_object(plan, "up", {.cascade = true});
  EXPECT_EQ(s.removed, (std::vector<std::string>{"up", "w", "d", "floor"}));
  EXPECT_TRUE(plan.levels.empty() && plan.walls.empty() && plan.openings.empty() &&
              plan.slabs.empty());
}

TEST(PlanEditV2, SlabsMoveTurnAndScaleLevelsHaveNoPosition) {
  Plan plan = storey_plan();
  move_object(plan, "floor", {1, 2});
  EXPECT_EQ(plan.slabs[0].outline[2], (Point2{5, 5}));
  rotate_object(plan, "floor", 90, Point2{1, 2});
  EXPECT_EQ(plan.slabs[0].outline[1], (Point2{1, 6}));
  scale_all(plan, 2, Point2{0, 0});
  EXPECT_EQ(plan.slabs[0].outline[1], (Point2{2, 12}));
  EXPECT_EQ(plan.walls[0].to, (Point2{8, 0}));
  EXPECT_EQ(code_of([&] { return move_object(plan, "up", {1, 0}); }), Code::precondition);
}

TEST(PlanEditV2, AddedSlabsNeedAnExistingLevel) {
  Plan plan = storey_plan();
  Slab s{.level = "nowhere"};
  s.outline = {{0, 0}, {1, 0}, {1, 1}};
  EXPECT_EQ(code_of([&] { return add_slab(plan, s); }), Code::precondition);
  s.level = "up";
  EXPECT_EQ(add_slab(plan, s).added, std::vector<std::string>{"slab-1"});
  EXPECT_EQ(add_level(plan, Level{}).added, std::vector<std::string>{"level-1"});
  EXPECT_TRUE(uses_version2(plan));
}

}  // namespace
}  // namespace roomcad
