// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad validate` and the rooms of `roomcad info`, run as a user would.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_command.h"

namespace roomcad {
namespace {

using test::run_roomcad;
using test::TempDir;

const char* const kTwoRooms = R"({
  "format": "roomcad-plan", "version": 1, "units": "m",
  "site": { "origin": [0, 0], "cells": [10, 6], "cell_size": 1.0, "max_height": 6.0 },
  "walls": [
    { "id": "s", "from": [1, 1], "to": [9, 1], "thickness": 0.2 },
    { "id": "e", "from": [9, 1], "to": [9, 5], "thickness": 0.2 },
    { "id": "n", "from": [9, 5], "to": [1, 5], "thickness": 0.2 },
    { "id": "w", "from": [1, 5], "to": [1, 1], "thickness": 0.2 },
    { "id": "m", "from": [5, 1], "to": [5, 5], "thickness": 0.2 }
  ],
  "openings": [
    { "id": "d", "type": "door", "wall": "m", "offset": 1.0 },
    { "id": "win1", "type": "window", "wall": "s", "offset": 1.0, "width": 1.2 },
    { "id": "win2", "type": "window", "wall": "s", "offset": 2.5, "width": 1.2 }
  ]
})";

/// Three errors of different kinds and one warning, to be reported in one run.
const char* const kBroken = R"({
  "format": "roomcad-plan", "version": 1, "units": "m",
  "site": { "origin": [0, 0], "cells": [6, 6], "cell_size": 1.0 },
  "walls": [
    { "id": "s", "from": [1, 1], "to": [5, 1], "thickness": 0.25 },
    { "id": "t", "from": [1, 1.1], "to": [5, 1.1], "thickness": 0.25 },
    { "id": "far", "from": [1, 3], "to": [7, 3], "thickness": 0.25 }
  ],
  "openings": [
    { "id": "w2", "type": "window", "wall": "far", "offset": 0.5, "width": 1.2, "colour": 1 },
    { "id": "w3", "type": "window", "wall": "nowhere", "offset": 0.5 }
  ]
})";

std::string write_plan(const TempDir& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  EXPECT_TRUE(test::write_bytes(path, text));
  return path.string();
}

TEST(ValidateCommand, ValidPlanIsOkWithRoomWarningsOnly) {
  TempDir dir;
  const auto r =
      run_roomcad({"validate", "--format", "json", write_plan(dir, "p.json", kTwoRooms)});
  EXPECT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["ok"], true);
  EXPECT_TRUE(j["errors"].empty());
  ASSERT_EQ(j["warnings"].size(), 1u);  // the east room has no window
  EXPECT_EQ(j["warnings"][0]["code"], "room_without_window");
  EXPECT_EQ(j["warnings"][0]["objects"], nlohmann::json({"e", "m", "n", "s"}));
}

TEST(ValidateCommand, AllProblemsInOneRunAsSpecJson) {
  TempDir dir;
  const auto r = run_roomcad({"validate", "--format", "json", write_plan(dir, "p.json", kBroken)});
  EXPECT_EQ(r.status, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["ok"], false);
  std::vector<std::string> codes;
  for (const auto& e : j["errors"]) {
    codes.push_back(e["code"]);
    EXPECT_TRUE(e.contains("objects") && e["objects"].is_array());
    EXPECT_TRUE(e["message"].is_string() && !e["message"].get<std::string>().empty());
  }
  EXPECT_EQ(codes,
            (std::vector<std::string>{"unknown_reference", "wall_overlap", "out_of_bounds"}));
  EXPECT_TRUE(j["errors"][1]["where"].is_array());
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0]["code"], "unknown_field");
}

TEST(ValidateCommand, TextNamesObjectsPlaceAndFixWithoutColourOffATerminal) {
  TempDir dir;
  const auto r = run_roomcad({"validate", write_plan(dir, "p.json", kBroken)});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("error[wall_overlap] s, t:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  at: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  fix: move t 0.15 m north"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reaches 1.00 m past the east edge"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("or enlarge the site to cells [7, 6]\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("3 errors, 1 warning"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\033'), std::string::npos);
}

// A real home with 1,421 findings: --max-findings prints the first in full, counts the rest,
// and the report ends with the findings by code and by level.
TEST(ValidateCommand, MaxFindingsPrintsTheFirstAndTheSummaryByCodeAndLevel) {
  const auto r = run_roomcad(
      {"validate", "--max-findings", "5",
       (test::source_dir() / "examples/sweethome3d/arif-putra-pertama-1.json").string()});
  EXPECT_EQ(r.status, 1);
  std::size_t blocks = 0;
  for (std::size_t at = r.out.find("\nerror["); at != std::string::npos;
       at = r.out.find("\nerror[", at + 1))
    ++blocks;
  EXPECT_EQ(blocks + (r.out.starts_with("error[") ? 1 : 0), 5u) << r.out;
  EXPECT_NE(r.out.find("... and 1416 more"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("by code:\n  wall_overlap      1208 errors\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("by level:\n  Level 0   106 errors\n"), std::string::npos) << r.out;
  EXPECT_LT(std::count(r.out.begin(), r.out.end(), '\n'), 40) << r.out;

  const auto bad = run_roomcad(
      {"validate", "--max-findings", "-1", (test::source_dir() / "examples/house.json").string()});
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_NE(bad.err.find("--max-findings"), std::string::npos) << bad.err;
}

// --format bcf writes a .bcfzip (read by bcf-js in IndependentReaders.Bcf*): the same file gives
// the same bytes; without -o, or -o without it, nothing runs.
TEST(ValidateCommand, BcfGoesToTheFileOfDashOAndIsTheSameBytesEveryRun) {
  TempDir dir;
  const std::string plan = write_plan(dir, "p.json", kBroken);
  const std::string a = (dir / "a.bcfzip").string(), b = (dir / "b.bcfzip").string();
  EXPECT_EQ(run_roomcad({"validate", plan, "--format", "bcf", "-o", a}).status, 1);
  EXPECT_EQ(run_roomcad({"validate", plan, "--format", "bcf", "-o", b}).status, 1);
  const std::string bytes = test::read_bytes(a);
  EXPECT_TRUE(bytes.starts_with("PK")) << bytes.substr(0, 8);
  EXPECT_EQ(test::read_bytes(b), bytes);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"validate", plan, "--format", "bcf"},
        std::vector<std::string>{"validate", plan, "-o", (dir / "c.bcfzip").string()}}) {
    const auto r = run_roomcad(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("-o,--output: give it with --format bcf"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "c.bcfzip"));
}

TEST(ValidateCommand, UnreadableFileIsExit2AndBadJsonIsAParseError) {
  TempDir dir;
  const auto missing = run_roomcad({"validate", (dir / "none.json").string()});
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(test::failure_code(missing), Code::io_error);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos);
  const auto bad =
      run_roomcad({"validate", "--format", "json", write_plan(dir, "bad.json", "{\"walls\": [")});
  EXPECT_EQ(bad.status, 1);
  const auto j = nlohmann::json::parse(bad.out);
  EXPECT_EQ(j["errors"][0]["code"], "parse_error");
  EXPECT_EQ(run_roomcad({"validate", "--format", "xml", (dir / "bad.json").string()}).status, 2);
}

TEST(InfoCommand, ListsRoomsWithClearAreas) {
  TempDir dir;
  const std::string plan = write_plan(dir, "p.json", kTwoRooms);
  const auto text = run_roomcad({"info", plan});
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("rooms     2"), std::string::npos) << text.out;
  EXPECT_NE(
      text.out.find("room 1  14.44 m2 clear  walls m, n, s, w  doors d  windows win1, win2\n"),
      std::string::npos)
      << text.out;
  const auto json = run_roomcad({"info", "--format", "json", plan});
  const auto j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["rooms"].size(), 2u);
  EXPECT_NEAR(j["rooms"][1]["area"].get<double>(), 3.8 * 3.8, 1e-9);
  EXPECT_TRUE(j["rooms"][1]["windows"].empty());
}

// The names the plan gives its rooms (`rooms[]`) follow their numbers.
TEST(InfoCommand, NamedRoomsShowTheirNames) {
  const auto r = run_roomcad({"info", (test::source_dir() / "examples/house.json").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("    room 1 (Entry)  13.16 m2 clear  walls coat_closet,"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("    room 6 (WC)  4.00 m2 clear"), std::string::npos) << r.out;
}

TEST(InfoCommand, RoomsAreFoundLevelByLevel) {
  // The bundled two-storey house: the first floor's partition stands over the ground floor's
  // living room, which is one room of 65 m2, not two halves.
  const std::string plan = (test::source_dir() / "examples/version2/two-storey.json").string();
  const auto text = run_roomcad({"info", plan});
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(
      text.out.find("rooms     3\n    room 1 of level 'ground'  65.33 m2 clear  walls bow, hall, "
                    "north, south, west  doors entry, hall_door"),
      std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("    room 2 of level 'first'  32.48 m2 clear"), std::string::npos)
      << text.out;
  const auto j = nlohmann::json::parse(run_roomcad({"info", "--format", "json", plan}).out);
  ASSERT_EQ(j["rooms"].size(), 3u);
  EXPECT_EQ(j["rooms"][0]["level"], "ground");
  EXPECT_EQ(j["rooms"][2]["level"], "first");
  EXPECT_EQ(j["rooms"][2]["name"], "room 2");
}

}  // namespace
}  // namespace roomcad
