// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad report`, run as a user would: one self-contained page whose plans carry every
// object's id and whose findings carry their code, objects, level and place; the exit status;
// --baseline and --level. (tests/python/test_report_page.py opens the page in Chromium.)
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/run_command.h"

namespace roomcad {
namespace {

using test::run_roomcad;
using test::TempDir;

/// Two walls drawn over each other and a window past its wall's end.
const char* const kBroken = R"({
  "format": "roomcad-plan", "version": 1, "units": "m",
  "site": { "origin": [0, 0], "cells": [12, 8], "cell_size": 1.0 },
  "walls": [
    { "id": "s", "from": [1, 1], "to": [9, 1], "thickness": 0.2 },
    { "id": "t", "from": [1, 1.1], "to": [9, 1.1], "thickness": 0.2 },
    { "id": "n", "from": [1, 5], "to": [9, 5], "thickness": 0.2 }
  ],
  "openings": [ { "id": "win", "type": "window", "wall": "n", "offset": 7.5, "width": 1.2 } ]
})";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string source(const char* relative) { return (test::source_dir() / relative).string(); }

TEST(ReportCommand, ThePageHoldsEveryObjectsIdAndFetchesNothing) {
  TempDir dir;
  const std::string page = (dir / "house.html").string();
  const auto r = run_roomcad({"report", source("examples/house.json"), "-o", page});
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string html = test::read_bytes(page);
  for (const char* id : {"south", "night_hall", "front_door", "bath_window", "wc", "bedroom_1"})
    EXPECT_NE(html.find(std::string("data-id=\"") + id + '"'), std::string::npos) << id;
  EXPECT_EQ(count(html, "class=\"wall\""), 21u);
  EXPECT_EQ(count(html, "class=\"opening\""), 26u);
  EXPECT_EQ(count(html, "<li class=\"finding"), 0u);
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  EXPECT_NE(html.find("<script>"), std::string::npos);
  // Nothing outside the file: no stylesheet, script or image fetched, no link away.
  for (const char* outside : {"<link", "src=\"http", "href=\"http", "<script src", "@import"})
    EXPECT_EQ(html.find(outside), std::string::npos) << outside;
  // The same plan, the same bytes.
  const std::string again = (dir / "again.html").string();
  EXPECT_EQ(run_roomcad({"report", source("examples/house.json"), "-o", again}).status, 0);
  EXPECT_EQ(test::read_bytes(again), html);
}

TEST(ReportCommand, EachFindingCarriesItsCodeObjectsAndPlace) {
  TempDir dir;
  const std::string plan = (dir / "plan.json").string();
  ASSERT_TRUE(test::write_bytes(plan, kBroken));
  const std::string page = (dir / "plan.html").string();
  const auto r = run_roomcad({"report", plan, "-o", page, "--picture", "off"});
  EXPECT_EQ(r.status, 1) << r.err;  // written, and the plan has errors
  const std::string html = test::read_bytes(page);
  EXPECT_EQ(count(html, "<li class=\"finding error\""), 2u) << html;
  EXPECT_NE(html.find("id=\"finding-1\" data-code=\"wall_overlap\" data-objects=\"s t\""),
            std::string::npos);
  EXPECT_NE(html.find("data-code=\"opening_outside_wall\" data-objects=\"win n\""),
            std::string::npos);
  EXPECT_TRUE(
      std::regex_search(html, std::regex("data-where=\"[-0-9.]+ [-0-9.]+ [-0-9.]+ [-0-9.]+\"")));
  EXPECT_NE(html.find("class=\"fail\">fails: 2 errors, 0 warnings"), std::string::npos);
  EXPECT_EQ(html.find("data:image/png"), std::string::npos);  // --picture off
}

TEST(ReportCommand, BaselineMarksFindingsNewOrUnchangedAndListsTheFixed) {
  TempDir dir;
  const std::string old_plan = (dir / "old.json").string();
  ASSERT_TRUE(test::write_bytes(old_plan, kBroken));
  std::string fixed = kBroken;  // the window moved inside its wall
  fixed.replace(fixed.find("\"offset\": 7.5"), 13, "\"offset\": 3.0");
  const std::string plan = (dir / "plan.json").string();
  ASSERT_TRUE(test::write_bytes(plan, fixed));
  const std::string page = (dir / "plan.html").string();
  const auto r =
      run_roomcad({"report", plan, "-o", page, "--baseline", old_plan, "--picture", "off"});
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string html = test::read_bytes(page);
  EXPECT_EQ(count(html, "<span class=\"status\">unchanged</span>"), 1u);
  EXPECT_EQ(count(html, "<span class=\"status\">new</span>"), 0u);
  EXPECT_NE(html.find("<li class=\"fixed error\" data-code=\"opening_outside_wall\""),
            std::string::npos);
}

// --repair lists the edits `roomcad repair` would make: on the apartment, a wall trimmed and
// two doors drawn over each other made one, each edit naming its object first.
TEST(ReportCommand, RepairListsTheEditsRepairWouldMake) {
  TempDir dir;
  const std::string page = (dir / "a.html").string();
  const auto r = run_roomcad({"report", source("examples/sweethome3d/1-BedroomApartment.json"),
                              "-o", page, "--repair", "--picture", "off"});
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string html = test::read_bytes(page);
  EXPECT_NE(html.find("<h2>Repair: 3 edits</h2>"), std::string::npos);
  EXPECT_NE(html.find("id=\"edit-1\" data-objects=\"wall5 wall4\""), std::string::npos);
  EXPECT_NE(html.find("trim &apos;wall5&apos;: clears 1 finding"), std::string::npos);
  EXPECT_EQ(count(html, "<li class=\"edit\""), 3u);
}

TEST(ReportCommand, BadArgumentsExit2AndWriteNothing) {
  TempDir dir;
  const std::string page = (dir / "x.html").string();
  const auto level =
      run_roomcad({"report", source("examples/house.json"), "-o", page, "--level", "attic"});
  EXPECT_EQ(level.status, 2);
  EXPECT_NE(level.err.find("--level: "), std::string::npos) << level.err;
  EXPECT_NE(level.err.find("no level 'attic'"), std::string::npos) << level.err;
  const auto missing = run_roomcad({"report", (dir / "none.json").string(), "-o", page});
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(page));
}

TEST(ReportCommand, LevelDrawsAndListsOneLevel) {
  TempDir dir;
  const std::string page = (dir / "two.html").string();
  const auto r = run_roomcad(
      {"report", source("examples/version2/two-storey.json"), "-o", page, "--level", "first"});
  EXPECT_LE(r.status, 1) << r.err;
  const std::string html = test::read_bytes(page);
  EXPECT_EQ(count(html, "<svg class=\"plan\""), 1u);
  EXPECT_NE(html.find("data-level=\"first\""), std::string::npos);
  EXPECT_EQ(html.find("data-level=\"ground\""), std::string::npos);
}

}  // namespace
}  // namespace roomcad
