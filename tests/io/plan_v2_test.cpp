// SPDX-License-Identifier: GPL-3.0-or-later
// Version 2 of the plan format through the reader and the writer: levels, slabs, sloped and
// arc walls, shaped openings; and what a version-1 file makes of version-2 fields.
#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "support/plan_reading.h"

namespace roomcad {
namespace {

/// The example of the plan format's "Version 2" section, as written there.
constexpr std::string_view kVersion2Example =
    R"({ "format": "roomcad-plan", "version": 2, "units": "m",
  "site": { "origin": [0, 0], "cells": [12, 8], "cell_size": 1.0, "max_height": 9.0,
            "chord_tolerance": 0.001 },
  "levels": [ { "id": "ground", "elevation": 0.0, "height": 2.8 },
              { "id": "first",  "elevation": 3.0, "height": 2.6 } ],
  "walls": [
    { "id": "s", "level": "ground", "from": [1, 1], "to": [11, 1], "thickness": 0.25, "height": 2.8 },
    { "id": "attic", "level": "first", "from": [1, 7], "to": [11, 7], "thickness": 0.2,
      "height": 0.4, "height_at_end": 2.4 },
    { "id": "bow", "level": "ground", "from": [11, 1], "to": [11, 7], "thickness": 0.25,
      "height": 2.8, "arc_extent": 60 } ],
  "openings": [
    { "id": "arch", "type": "window", "wall": "s", "offset": 2, "width": 1.2, "height": 1.6,
      "sill": 0.8, "shape": [[0, 0], [1, 0], [1, 0.7], [0.85, 0.93], [0.5, 1], [0.15, 0.93], [0, 0.7]] } ],
  "slabs": [
    { "id": "first_floor", "level": "first", "outline": [[1, 1], [11, 1], [11, 7], [1, 7]],
      "holes": [[[2, 5], [4, 5], [4, 6], [2, 6]]], "top": 0.0, "thickness": 0.2 } ]
}
)";

TEST(PlanVersion2, TheFormatsExampleReadsEveryField) {
  const test::PlanReading r = test::read_plan(kVersion2Example);
  ASSERT_TRUE(r.plan) << (r.report.items.empty() ? "" : r.report.items[0].message);
  EXPECT_TRUE(r.report.items.empty());
  const Plan& p = *r.plan;
  EXPECT_EQ(p.site.chord_tolerance, 0.001);
  ASSERT_EQ(p.levels.size(), 2u);
  EXPECT_EQ(p.levels[1].id, "first");
  EXPECT_EQ(p.levels[1].elevation, 3.0);
  EXPECT_EQ(p.levels[1].height, 2.6);
  ASSERT_EQ(p.walls.size(), 3u);
  EXPECT_EQ(p.walls[1].level, "first");
  EXPECT_EQ(p.walls[1].height_at_end, 2.4);
  EXPECT_EQ(p.walls[0].height_at_end, std::nullopt);
  EXPECT_EQ(p.walls[2].arc_extent, 60.0);
  ASSERT_EQ(p.openings.size(), 1u);
  ASSERT_EQ(p.openings[0].shape.size(), 7u);
  EXPECT_EQ(p.openings[0].shape[3], (Point2{0.85, 0.93}));
  ASSERT_EQ(p.slabs.size(), 1u);
  EXPECT_EQ(p.slabs[0].outline.size(), 4u);
  ASSERT_EQ(p.slabs[0].holes.size(), 1u);
  EXPECT_EQ(p.slabs[0].holes[0][2], (Point2{4, 6}));
  EXPECT_EQ(p.slabs[0].thickness, 0.2);
}

TEST(PlanVersion2, WritesVersion2AndReadsBackTheSamePlan) {
  const Plan plan = *read_plan_text(kVersion2Example, "v2.json");
  const std::string text = write_plan_text(plan);
  EXPECT_NE(text.find("\"version\": 2"), std::string::npos);
  EXPECT_NE(text.find("\"levels\": ["), std::string::npos);
  EXPECT_NE(text.find("\"holes\": [[[2, 5], [4, 5], [4, 6], [2, 6]]]"), std::string::npos) << text;
  const Result<Plan> again = read_plan_text(text, "again.json");
  ASSERT_TRUE(again.ok()) << again.error();
  EXPECT_EQ(*again, plan);
  EXPECT_EQ(write_plan_text(*again), text);
}

TEST(PlanVersion2, APlanWithoutVersion2FieldsIsWrittenAsVersion1) {
  const std::string text =
      R"({"version": 2, "walls": [{"id": "a", "from": [0, 0], "to": [1, 0]}]})";
  const Result<Plan> plan = read_plan_text(text, "p.json");
  ASSERT_TRUE(plan.ok());
  const std::string written = write_plan_text(*plan);
  EXPECT_NE(written.find("\"version\": 1"), std::string::npos);
  EXPECT_EQ(written.find("level"), std::string::npos);
  EXPECT_EQ(written.find("height_at_end"), std::string::npos);
}

TEST(PlanVersion2, AWallOfALevelWithoutAHeightTakesTheLevels) {
  const Result<Plan> plan = read_plan_text(R"({"version": 2,
    "walls": [{"id": "a", "level": "up", "from": [0, 0], "to": [1, 0]},
              {"id": "b", "level": "up", "from": [0, 1], "to": [1, 1], "height": 2}],
    "levels": [{"id": "up", "elevation": 3, "height": 2.6}]})",
                                           "p.json");
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_EQ(plan->walls[0].height, 2.6);
  EXPECT_EQ(plan->walls[1].height, 2.0);
}

TEST(PlanVersion2, Version2FieldsInAVersion1FileAreKeptUnusedWithAWarning) {
  const std::string text = R"({"version": 1, "levels": [{"id": "up", "elevation": 3}],
    "walls": [{"id": "a", "from": [0, 0], "to": [1, 0], "height_at_end": 2}]})";
  const test::PlanReading r = test::read_plan(text);
  ASSERT_TRUE(r.plan);
  EXPECT_TRUE(r.plan->levels.empty());
  EXPECT_EQ(r.plan->walls[0].height_at_end, std::nullopt);
  ASSERT_EQ(r.report.items.size(), 2u);
  for (const Diagnostic& d : r.report.items) {
    EXPECT_EQ(d.code, Code::unknown_field);
    EXPECT_EQ(d.severity, Severity::warning);
    EXPECT_NE(d.message.find("is a version 2 field and this file is version 1"), std::string::npos);
    EXPECT_EQ(d.fix, "set \"version\": 2 to use it");
  }
  const std::string written = write_plan_text(*r.plan);
  EXPECT_NE(written.find("\"version\": 1"), std::string::npos);
  EXPECT_NE(written.find("\"levels\": [{\"elevation\": 3, \"id\": \"up\"}]"), std::string::npos)
      << written;
  EXPECT_NE(written.find("\"height_at_end\": 2"), std::string::npos) << written;
}

TEST(PlanVersion2, WrongTypesAndMissingFieldsOfTheNewObjects) {
  const test::PlanReading r = test::read_plan(R"({"version": 2,
    "levels": [{"id": "up"}],
    "slabs": [{"id": "s", "outline": [[0, 0], [1]], "holes": 3}],
    "openings": [{"id": "o", "wall": "w", "offset": 0, "shape": "round"}]})");
  EXPECT_FALSE(r.plan);
  std::vector<std::pair<Code, std::string>> found;
  for (const Diagnostic& d : r.report.items) found.emplace_back(d.code, d.location->pointer);
  EXPECT_EQ(found,
            (std::vector<std::pair<Code, std::string>>{{Code::parse_error, "/levels/0"},
                                                       {Code::parse_error, "/slabs/0/outline/1"},
                                                       {Code::parse_error, "/slabs/0/holes"},
                                                       {Code::parse_error, "/openings/0/shape"}}));
}

}  // namespace
}  // namespace roomcad
