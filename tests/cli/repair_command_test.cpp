// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad repair` and `roomcad import --repair`, run as a user would: the report's JSON as
// docs/plan-format.md ("Repair") spells it, the exit status, what is written and when not.
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_command.h"

namespace roomcad {
namespace {

using test::run_roomcad;
using test::TempDir;

/// A wall drawn twice over part of another (with a door on the copy), and one drawn 4 cm off
/// another's line: the first clears, the second needs more than the default tolerance.
const char* const kSloppy = R"({
  "format": "roomcad-plan", "version": 1, "units": "m",
  "site": { "origin": [0, 0], "cells": [12, 8], "cell_size": 1.0 },
  "walls": [
    { "id": "a", "from": [1, 1], "to": [9, 1], "thickness": 0.2, "height": 2.5 },
    { "id": "b", "from": [3, 1], "to": [7, 1], "thickness": 0.2, "height": 2.5 },
    { "id": "c", "from": [1, 5], "to": [9, 5], "thickness": 0.2, "height": 2.5 },
    { "id": "d", "from": [3, 5.04], "to": [7, 5.04], "thickness": 0.2, "height": 3.0 }
  ],
  "openings": [ { "id": "door", "type": "door", "wall": "b", "offset": 1.0 } ]
})";

std::string write_plan(const TempDir& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  EXPECT_TRUE(test::write_bytes(path, text));
  return path.string();
}

TEST(RepairCommand, JsonReportsEditsCountsAndWhatRemainsWithWhy) {
  TempDir dir;
  const std::string plan = write_plan(dir, "plan.json", kSloppy);
  const std::string out = (dir / "out.json").string();
  const auto r = run_roomcad({"repair", plan, "-o", out, "--format", "json"});
  EXPECT_EQ(r.status, 1) << r.err;  // d and c remain
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["tolerance"], 0.01);
  EXPECT_EQ(json["before"]["wall_overlap"], 2);
  EXPECT_EQ(json["before"]["opening_blocked"], 1);
  EXPECT_EQ(json["after"], nlohmann::json({{"wall_overlap", 1}}));
  ASSERT_FALSE(json["edits"].empty());
  for (const auto& e : json["edits"]) {
    for (const char* key : {"object", "change", "old", "new", "clears", "moves"})
      EXPECT_TRUE(e.contains(key)) << key << " in " << e;
  }
  const auto& removal = json["edits"].back();
  EXPECT_EQ(removal["object"], "b");
  EXPECT_EQ(removal["change"], "delete");
  EXPECT_EQ(removal["moves"], 0.0);
  ASSERT_EQ(json["remaining"].size(), 1u);
  EXPECT_EQ(json["remaining"][0]["code"], "wall_overlap");
  EXPECT_EQ(json["remaining"][0]["objects"], nlohmann::json({"c", "d"}));
  EXPECT_NE(json["remaining"][0]["reason"].get<std::string>().find("tolerance"), std::string::npos);
  // The door stands where it stood, on the wall that now holds it.
  const auto written = nlohmann::json::parse(test::read_bytes(out));
  EXPECT_EQ(written["openings"][0]["wall"], "a");
  EXPECT_EQ(written["openings"][0]["offset"], 3.0);
  // A larger tolerance clears the rest.
  const auto wide = run_roomcad({"repair", plan, "-o", out, "--tolerance", "0.05"});
  EXPECT_EQ(wide.status, 0) << wide.out << wide.err;
}

TEST(RepairCommand, DryRunWritesNothingAndTextSaysWhatItWouldDo) {
  TempDir dir;
  const std::string plan = write_plan(dir, "plan.json", kSloppy);
  const auto r = run_roomcad({"repair", plan, "--dry-run"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("dry run"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("delete 'b'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("left because"), std::string::npos) << r.out;
  EXPECT_EQ(test::read_bytes(plan), kSloppy);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(RepairCommand, APlanWithNothingToRepairIsWrittenByteForByte) {
  TempDir dir;
  const std::string source = std::string(ROOMCAD_SOURCE_DIR) + "/examples/house.json";
  const std::string out = (dir / "house.json").string();
  const auto r = run_roomcad({"repair", source, "-o", out});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_bytes(out), test::read_bytes(source));
}

TEST(RepairCommand, RepairingInPlaceTwiceChangesNothingTheSecondTime) {
  TempDir dir;
  const std::string plan = write_plan(dir, "plan.json", kSloppy);
  ASSERT_EQ(run_roomcad({"repair", plan, "-o", plan}).status, 1);
  const std::string once = test::read_bytes(plan);
  const auto again = run_roomcad({"repair", plan, "-o", plan, "--format", "json"});
  EXPECT_TRUE(nlohmann::json::parse(again.out)["edits"].empty());
  EXPECT_EQ(test::read_bytes(plan), once);
}

TEST(RepairCommand, OnlyRepairsTheCodesGiven) {
  TempDir dir;
  const std::string plan = write_plan(dir, "plan.json", kSloppy);
  const auto r = run_roomcad({"repair", plan, "--dry-run", "--format", "json", "--only",
                              "opening_outside_wall,slab_overlap"});
  EXPECT_TRUE(nlohmann::json::parse(r.out)["edits"].empty());
}

TEST(RepairCommand, BadArgumentsNameTheValueAndExit2) {
  TempDir dir;
  const std::string plan = write_plan(dir, "plan.json", kSloppy);
  const auto no_output = run_roomcad({"repair", plan});
  EXPECT_EQ(no_output.status, 2);
  EXPECT_NE(no_output.err.find("-o/--output"), std::string::npos) << no_output.err;
  const auto code = run_roomcad({"repair", plan, "--dry-run", "--only", "wall_overlaps"});
  EXPECT_EQ(code.status, 2);
  EXPECT_NE(code.err.find("'wall_overlaps'"), std::string::npos) << code.err;
  const auto tolerance = run_roomcad({"repair", plan, "--dry-run", "--tolerance", "-1"});
  EXPECT_EQ(tolerance.status, 2);
  EXPECT_NE(tolerance.err.find("tolerance"), std::string::npos) << tolerance.err;
  const auto missing = run_roomcad({"repair", (dir / "none.json").string(), "--dry-run"});
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
}

TEST(RepairCommand, ImportRepairWritesTheRepairedHome) {
  TempDir dir;
  const std::string home =
      std::string(ROOMCAD_SOURCE_DIR) +
      "/examples/sweethome3d/homes/eteks-example-homes/1-BedroomApartment.Home.xml";
  const std::string out = (dir / "home.json").string();
  const auto r = run_roomcad({"import", home, "-o", out, "--repair"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("repair: 3 edits clear 2 of 2 errors"), std::string::npos) << r.err;
  EXPECT_EQ(run_roomcad({"validate", out}).status, 0);
}

TEST(RepairCommand, TheReadmeTourImportsValidatesRepairsAndBuilds) {
  TempDir dir;
  const std::string home =
      std::string(ROOMCAD_SOURCE_DIR) +
      "/examples/sweethome3d/homes/eteks-example-homes/1-BedroomApartment.Home.xml";
  const std::string plan = (dir / "apartment.json").string();
  ASSERT_EQ(run_roomcad({"import", home, "-o", plan}).status, 0);
  const auto validated = run_roomcad({"validate", plan});
  EXPECT_EQ(validated.status, 1);
  EXPECT_NE(validated.out.find("2 errors"), std::string::npos) << validated.out;
  const auto repaired = run_roomcad({"repair", plan, "-o", plan});
  EXPECT_EQ(repaired.status, 0) << repaired.out << repaired.err;
  EXPECT_NE(
      repaired.out.find("3 edits clear 2 of 2 errors, 0 remain; the solid moves at most 0 mm"),
      std::string::npos)
      << repaired.out;
  const auto built =
      run_roomcad({"build", plan, "-o", (dir / "apartment.obj").string(), "--check"});
  EXPECT_EQ(built.status, 0) << built.err;
}

}  // namespace
}  // namespace roomcad
