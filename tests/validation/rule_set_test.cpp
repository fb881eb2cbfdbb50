// SPDX-License-Identifier: GPL-3.0-or-later
// Built-in rule sets and the rules file: what each enables, thresholds and severities, and a
// usage_error naming the file, the field and the value for every bad file.
#include <gtest/gtest.h>

#include "plan_cases.h"
#include "validation/rule_set.h"

namespace roomcad {
namespace {

TEST(RuleSet, BuiltInSets) {
  const RuleSet none = *builtin_rule_set("default");
  EXPECT_FALSE(none.any_enabled());
  const RuleSet all = *builtin_rule_set("all");
  for (const Code c : kRuleCodes) EXPECT_TRUE(all.is_enabled(c)) << c;
  const RuleSet access = *builtin_rule_set("accessibility");
  for (const Code c : {Code::door_too_narrow, Code::door_clearance, Code::passage_too_narrow,
                       Code::no_turning_circle, Code::room_unreachable})
    EXPECT_TRUE(access.is_enabled(c)) << c;
  for (const Code c : {Code::door_swing_blocked, Code::window_sill_low, Code::duplicate_object})
    EXPECT_FALSE(access.is_enabled(c)) << c;
  EXPECT_FALSE(builtin_rule_set("everything").has_value());
  EXPECT_FALSE(all.is_enabled(Code::wall_overlap));  // not a rule
}

TEST(RuleSet, DefaultsAreTheFormats) {
  const RuleThresholds t;
  EXPECT_EQ(t.clearance_width, 1.5);
  EXPECT_EQ(t.clearance_depth, 1.5);
  EXPECT_EQ(t.door_min_width, 0.80);
  EXPECT_EQ(t.passage_min_width, 0.90);
  EXPECT_EQ(t.turning_diameter, 1.5);
  EXPECT_EQ(t.escape_max_distance, 30.0);
}

TEST(RuleSetFile, EnablesRulesSetsThresholdsSeveritiesAndRooms) {
  const Result<RuleSet> r = parse_rule_set(R"({
    "format": "roomcad-rules", "version": 1, "base": "accessibility",
    "rules": {
      "door_clearance": { "width": 1.2, "depth": 1.2, "severity": "error" },
      "no_turning_circle": false,
      "window_sill_low": { "min_sill": 0.6 },
      "escape_too_far": true
    },
    "accessible_rooms": [[2, 3], [7.5, 1]]
  })",
                                           "r.json");
  ASSERT_TRUE(r) << r.error().message;
  const RuleSet& s = r.value();
  EXPECT_TRUE(s.is_enabled(Code::door_clearance));
  EXPECT_TRUE(s.is_enabled(Code::door_too_narrow));  // from the base
  EXPECT_FALSE(s.is_enabled(Code::no_turning_circle));
  EXPECT_TRUE(s.is_enabled(Code::window_sill_low));
  EXPECT_TRUE(s.is_enabled(Code::escape_too_far));
  EXPECT_FALSE(s.is_enabled(Code::duplicate_object));
  EXPECT_EQ(s.thresholds.clearance_width, 1.2);
  EXPECT_EQ(s.thresholds.window_min_sill, 0.6);
  EXPECT_EQ(s.severity[*rule_index(Code::door_clearance)], Severity::error);
  EXPECT_EQ(s.severity[*rule_index(Code::door_too_narrow)], Severity::warning);
  ASSERT_TRUE(s.accessible_rooms.has_value());
  EXPECT_EQ(s.accessible_rooms->size(), 2u);
  EXPECT_EQ(s.name, "r.json");
}

TEST(RuleSetFile, EveryBadFileIsAUsageErrorNamingTheField) {
  const std::pair<const char*, const char*> cases[] = {
      {"{", "invalid JSON"},
      {"[1]", "/: expected a JSON object"},
      {R"({"rulez": {}})", "/rulez: unknown field \"rulez\" (did you mean \"rules\"?)"},
      {R"({"format": "roomcad-plan"})", "/format: expected \"roomcad-rules\""},
      {R"({"base": "most"})", "/base: unknown rule set \"most\""},
      {R"({"rules": {"door_swing_blokced": true}})",
       "/rules/door_swing_blokced: unknown rule \"door_swing_blokced\" (did you mean "
       "\"door_swing_blocked\"?)"},
      {R"({"rules": {"wall_overlap": true}})",
       "/rules/wall_overlap: unknown rule \"wall_overlap\" (known: door_swing_blocked, "},
      {R"({"rules": {"door_too_narrow": {"min_width": -1}}})",
       "/rules/door_too_narrow/min_width: expected a positive number"},
      {R"({"rules": {"door_too_narrow": {"min_width": "0.8"}}})",
       "/rules/door_too_narrow/min_width: expected a positive number"},
      {R"({"rules": {"door_too_narrow": {"depth": 1}}})",
       "/rules/door_too_narrow/depth: unknown setting of door_too_narrow"},
      {R"({"rules": {"door_clearance": {"severity": "fatal"}}})",
       "/rules/door_clearance/severity: expected \"warning\" or \"error\""},
      {R"({"rules": {"door_clearance": 1}})",
       "/rules/door_clearance: expected true, false or an object"},
      {R"({"accessible_rooms": [[1, 2], [3]]})", "/accessible_rooms/1: expected a point [x, y]"},
  };
  for (const auto& [text, expected] : cases) {
    const Result<RuleSet> r = parse_rule_set(text, "bad.json");
    ASSERT_FALSE(r) << text;
    EXPECT_EQ(r.error().code, Code::usage_error) << text;
    EXPECT_EQ(exit_status_of(r.error().code), kExitCannotRun);
    EXPECT_NE(r.error().message.find("bad.json"), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find(expected), std::string::npos) << r.error().message;
  }
}

TEST(RuleSetFile, AccessibleRoomOutsideEveryRoomIsRefused) {
  Plan plan = testing::plan_with({});
  plan.walls = {testing::make_wall("s", {0, 0}, {4, 0}), testing::make_wall("e", {4, 0}, {4, 4}),
                testing::make_wall("n", {4, 4}, {0, 4}), testing::make_wall("w", {0, 4}, {0, 0})};
  RuleSet rules = *builtin_rule_set("accessibility");
  rules.name = "r.json";
  rules.accessible_rooms = std::vector<Point2>{{2, 2}};
  EXPECT_TRUE(check_accessible_rooms(plan, rules));
  rules.accessible_rooms->push_back({9, 9});
  const Status s = check_accessible_rooms(plan, rules);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, Code::usage_error);
  EXPECT_NE(s.error().message.find("r.json: /accessible_rooms/1: the point [9, 9] lies in no room"),
            std::string::npos)
      << s.error().message;
}

}  // namespace
}  // namespace roomcad
