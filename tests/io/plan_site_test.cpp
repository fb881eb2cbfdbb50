// SPDX-License-Identifier: GPL-3.0-or-later
// Version 2's site location, north and obstructions through the reader, the writer, the edits
// and validation: the example of the format's "where the site is" section, as written there.
#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "plan/plan_add.h"
#include "plan/plan_edit.h"
#include "support/plan_reading.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

constexpr std::string_view kSiteExample =
    R"({ "format": "roomcad-plan", "version": 2, "units": "m",
  "site": { "origin": [0, 0], "cells": [12, 8], "cell_size": 1.0, "max_height": 9.0,
            "location": { "latitude": 55.75, "longitude": 37.62, "utc_offset": 3 },
            "north": 0 },
  "obstructions": [
    { "id": "block_b", "outline": [[-20, -30], [30, -30], [30, -24], [-20, -24]],
      "base": 0, "height": 18 } ] }
)";

TEST(PlanSite, TheFormatsExampleReadsEveryField) {
  const test::PlanReading r = test::read_plan(kSiteExample);
  ASSERT_TRUE(r.plan);
  EXPECT_TRUE(r.report.items.empty());
  const Plan& p = *r.plan;
  ASSERT_TRUE(p.site.location);
  EXPECT_EQ(p.site.location->latitude, 55.75);
  EXPECT_EQ(p.site.location->longitude, 37.62);
  EXPECT_EQ(p.site.location->utc_offset, 3.0);
  EXPECT_EQ(p.site.north, 0.0);
  ASSERT_EQ(p.obstructions.size(), 1u);
  EXPECT_EQ(p.obstructions[0].outline[2], (Point2{30, -24}));
  EXPECT_EQ(p.obstructions[0].height, 18.0);
  EXPECT_TRUE(validate(p).ok());  // off the site is allowed: out_of_bounds does not apply
}

TEST(PlanSite, WritesAndReadsBackTheSamePlan) {
  const Plan plan = *read_plan_text(kSiteExample, "site.json");
  const std::string text = write_plan_text(plan);
  EXPECT_NE(
      text.find("\"location\": {\"latitude\": 55.75, \"longitude\": 37.62, \"utc_offset\": 3}"),
      std::string::npos);
  EXPECT_EQ(*read_plan_text(text, "again.json"), plan);
}

TEST(PlanSite, AVersion1FileKeepsObstructionsAsUnknown) {
  std::string v1(kSiteExample);
  v1.replace(v1.find("\"version\": 2"), 12, "\"version\": 1");
  const test::PlanReading r = test::read_plan(v1);
  ASSERT_TRUE(r.plan);
  EXPECT_TRUE(r.plan->obstructions.empty());
  EXPECT_FALSE(r.plan->site.location);
  ASSERT_FALSE(r.report.items.empty());
  EXPECT_NE(r.report.items[0].message.find("version 2"), std::string::npos);
  EXPECT_NE(write_plan_text(*r.plan).find("\"obstructions\""), std::string::npos);  // kept
}

TEST(PlanSite, OutOfRangeLocationIsAnInvalidValue) {
  Plan plan = *read_plan_text(kSiteExample, "site.json");
  plan.site.location->latitude = 91;
  plan.site.location->utc_offset = -13;
  const Report report = validate(plan);
  ASSERT_EQ(report.items.size(), 2u);
  EXPECT_EQ(report.items[0].code, Code::invalid_value);
  EXPECT_NE(report.items[0].message.find("latitude is 91"), std::string::npos);
  EXPECT_NE(report.items[1].message.find("utc_offset is -13"), std::string::npos);
}

TEST(PlanSite, SetAndAddTakeLocationAndObstructions) {
  Plan plan = *read_plan_text(kSiteExample, "site.json");
  ASSERT_TRUE(set_field(plan, "site", "location", "48.85,2.35,1", "set"));
  EXPECT_EQ(plan.site.location, (GeoLocation{48.85, 2.35, 1, {}}));
  EXPECT_FALSE(set_field(plan, "site", "location", "north", "set"));
  ASSERT_TRUE(add_object(plan, "obstruction", "tree",
                         {{"outline", "40,0;42,0;42,2;40,2"}, {"height", "8"}}));
  EXPECT_EQ(plan.obstructions.back().height, 8.0);
  EXPECT_FALSE(add_object(plan, "obstruction", "bush", {{"outline", "40,0;42,0;42,2"}}))
      << "height is required";
}

TEST(PlanSite, AnObstructionInAWallOrSlabIsAnError) {
  Plan plan = *read_plan_text(kSiteExample, "site.json");
  plan.walls.push_back(Wall{.id = "w", .from = {1, 1}, .to = {5, 1}});
  plan.obstructions.push_back(
      Obstruction{.id = "shed", .outline = {{2, 0}, {3, 0}, {3, 2}, {2, 2}}, .height = 2});
  Report report = validate(plan);
  ASSERT_EQ(report.items.size(), 1u);
  EXPECT_EQ(report.items[0].code, Code::obstruction_overlap);
  EXPECT_EQ(report.items[0].objects, (std::vector<std::string>{"shed", "w"}));
  plan.obstructions.back().base = 2.8;  // on top of the wall: touching is not sharing
  EXPECT_TRUE(validate(plan).ok());
  plan.obstructions.back().outline = {{2, 1.125}, {3, 1.125}, {3, 2}, {2, 2}};  // beside it
  plan.obstructions.back().base = 0;
  EXPECT_TRUE(validate(plan).ok());
}

TEST(PlanSite, TurningThePlanTurnsNorth) {
  Plan plan = *read_plan_text(kSiteExample, "site.json");
  rotate_all(plan, 90, Point2{0, 0});
  EXPECT_EQ(plan.site.north, 90.0);
  Plan without;  // a plan that does not say where north is keeps saying nothing
  rotate_all(without, 90, Point2{0, 0});
  EXPECT_FALSE(without.site.north);
}

}  // namespace
}  // namespace roomcad
