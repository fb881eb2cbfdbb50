// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad validate --rules/--baseline` and `roomcad draw --findings`, run as a user would:
// codes in JSON, fixes as commands that work, revisions, bad rule files, marks on the plan.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_command.h"

namespace roomcad {
namespace {

using test::run_roomcad;
using test::TempDir;

// A 4 x 4 m room whose entry door is 0.7 m wide and whose window sill is 0.3 m.
const char* const kRoom = R"({
  "format": "roomcad-plan", "version": 1, "units": "m",
  "site": { "origin": [0, 0], "cells": [8, 8], "cell_size": 1.0 },
  "walls": [
    { "id": "s", "from": [2, 2], "to": [6, 2], "thickness": 0.2 },
    { "id": "e", "from": [6, 2], "to": [6, 6], "thickness": 0.2 },
    { "id": "n", "from": [6, 6], "to": [2, 6], "thickness": 0.2 },
    { "id": "w", "from": [2, 6], "to": [2, 2], "thickness": 0.2 }
  ],
  "openings": [
    { "id": "d", "type": "door", "wall": "s", "offset": 1.5, "width": 0.7 },
    { "id": "win", "type": "window", "wall": "n", "offset": 1.0, "width": 1.2, "sill": 0.3 }
  ]
})";

std::string write_file(const TempDir& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  EXPECT_TRUE(test::write_bytes(path, text));
  return path.string();
}

std::vector<std::string> codes(const nlohmann::json& items) {
  std::vector<std::string> out;
  for (const auto& item : items) out.push_back(item["code"]);
  return out;
}

TEST(RulesCommand, DefaultRulesAreTheFormatsChecksAndAllAddsTheRules) {
  TempDir dir;
  const std::string plan = write_file(dir, "p.json", kRoom);
  const auto plain = run_roomcad({"validate", "--format", "json", plan});
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(codes(nlohmann::json::parse(plain.out)["warnings"]), std::vector<std::string>{});
  const auto all = run_roomcad({"validate", "--format", "json", "--rules", "all", plan});
  ASSERT_EQ(all.status, 0) << all.err;  // rule findings are warnings
  const auto j = nlohmann::json::parse(all.out);
  EXPECT_EQ(codes(j["warnings"]), (std::vector<std::string>{"door_too_narrow", "window_sill_low"}));
  EXPECT_EQ(j["warnings"][0]["id"], "door_too_narrow:d");
  // Widened about its middle: 5 cm to each side.
  EXPECT_EQ(j["warnings"][0]["edits"][0]["command"],
            "roomcad set " + plan + " d offset=1.45 width=0.8");
}

TEST(RulesCommand, FixCommandsPrintedByValidateRemoveTheFindings) {
  TempDir dir;
  const std::string plan = write_file(dir, "p.json", kRoom);
  const auto j = nlohmann::json::parse(
      run_roomcad({"validate", "--format", "json", "--rules", "all", plan}).out);
  for (const auto& finding : j["warnings"]) {
    for (const auto& edit : finding["edits"]) {
      ASSERT_EQ(edit["op"], "set");
      std::vector<std::string> args{"set", plan, edit["id"]};
      for (const auto& [key, value] : edit["fields"].items())
        args.push_back(key + "=" + value.get<std::string>());
      const auto run = run_roomcad(args);
      EXPECT_EQ(run.status, 0) << run.err;
    }
  }
  const auto after = run_roomcad({"validate", "--rules", "all", plan});
  EXPECT_EQ(after.status, 0);
  EXPECT_NE(after.out.find("no problems"), std::string::npos) << after.out;
}

TEST(RulesCommand, RulesFileSetsThresholdsAndSeverities) {
  TempDir dir;
  const std::string plan = write_file(dir, "p.json", kRoom);
  const std::string rules =
      write_file(dir, "r.json", R"({"rules": {"door_too_narrow": {"min_width": 0.7},
      "window_sill_low": {"min_sill": 0.3, "severity": "error"}, "room_unreachable": {"severity": "error"}}})");
  const auto run = run_roomcad({"validate", "--format", "json", "--rules", rules, plan});
  EXPECT_EQ(run.status, 0) << run.out;  // 0.7 and 0.3 are at the thresholds; the room has a door
  const std::string tight =
      write_file(dir, "t.json", R"({"rules": {"window_sill_low": {"severity": "error"}}})");
  const auto failing = run_roomcad({"validate", "--format", "json", "--rules", tight, plan});
  EXPECT_EQ(failing.status, 1);
  EXPECT_EQ(codes(nlohmann::json::parse(failing.out)["errors"]),
            std::vector<std::string>{"window_sill_low"});
}

TEST(RulesCommand, BadRulesAreExit2NamingFileFieldAndValue) {
  TempDir dir;
  const std::string plan = write_file(dir, "p.json", kRoom);
  const auto unknown = run_roomcad({"validate", "--rules", "strict", plan});
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("--rules \"strict\": neither a rule set (default, accessibility, "
                             "insolation, all) nor a rules file"),
            std::string::npos)
      << unknown.err;
  const std::string bad =
      write_file(dir, "bad.json", R"({"rules": {"door_too_narrow": {"min_width": 0}}})");
  const auto run = run_roomcad({"validate", "--rules", bad, plan});
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find(bad + ": /rules/door_too_narrow/min_width: expected a positive number"),
            std::string::npos)
      << run.err;
  const std::string room = write_file(dir, "room.json", R"({"accessible_rooms": [[0.5, 0.5]]})");
  const auto outside = run_roomcad({"validate", "--rules", room, plan});
  EXPECT_EQ(outside.status, 2);
  EXPECT_NE(outside.err.find("/accessible_rooms/0: the point [0.5, 0.5] lies in no room"),
            std::string::npos)
      << outside.err;
}

TEST(RulesCommand, BaselineReportsNewUnchangedAndFixed) {
  TempDir dir;
  const std::string old_plan = write_file(dir, "old.json", kRoom);
  const std::string new_plan = write_file(dir, "new.json", kRoom);
  ASSERT_EQ(run_roomcad({"set", new_plan, "d", "width=0.9"}).status, 0);  // fixes door_too_narrow
  ASSERT_EQ(run_roomcad({"set", new_plan, "win", "sill=1.5", "height=0.6"}).status,
            0);  // low -> high
  const auto run = run_roomcad(
      {"validate", "--format", "json", "--rules", "all", "--baseline", old_plan, new_plan});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0]["code"], "window_sill_high");
  EXPECT_EQ(j["warnings"][0]["status"], "new");
  EXPECT_EQ(j["baseline"]["new"], 1);
  EXPECT_EQ(j["baseline"]["unchanged"], 0);
  EXPECT_EQ(codes(j["baseline"]["fixed"]),
            (std::vector<std::string>{"door_too_narrow", "window_sill_low"}));
  const auto text = run_roomcad({"validate", "--rules", "all", "--baseline", old_plan, new_plan});
  EXPECT_NE(text.out.find("against " + old_plan + ": 1 new, 0 unchanged, 2 fixed"),
            std::string::npos)
      << text.out;
  EXPECT_EQ(
      run_roomcad({"validate", "--baseline", (dir / "missing.json").string(), new_plan}).status, 2);
}

TEST(RulesCommand, DrawMarksFindingsInRedWithTheirCodes) {
  TempDir dir;
  const std::string plan = write_file(dir, "p.json", kRoom);
  const std::string svg = (dir / "p.svg").string();
  const auto run = run_roomcad({"draw", plan, "--findings", "-o", svg});
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string text = test::read_bytes(svg);
  EXPECT_NE(text.find("<g id=\"findings\" class=\"findings\" stroke=\"#d00000\""),
            std::string::npos);
  for (const char* code : {">door_too_narrow<", ">window_sill_low<"})
    EXPECT_NE(text.find(code), std::string::npos) << code;
  ASSERT_EQ(run_roomcad({"draw", plan, "--findings", "--rules", "default", "-o", svg}).status, 0);
  EXPECT_EQ(test::read_bytes(svg).find("id=\"findings\""), std::string::npos);  // nothing to mark
  ASSERT_EQ(run_roomcad({"draw", plan, "-o", svg}).status, 0);
  EXPECT_EQ(test::read_bytes(svg).find("door_too_narrow"), std::string::npos);
  EXPECT_EQ(run_roomcad({"draw", plan, "--findings", "--view", "iso", "-o", svg}).status, 2);
}

}  // namespace
}  // namespace roomcad
