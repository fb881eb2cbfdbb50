// SPDX-License-Identifier: GPL-3.0-or-later
// Printing reports: the spec's JSON object and the text for people.
#include <string>

#include <gtest/gtest.h>

#include "validation/report_diff.h"
#include "validation/report_format.h"

namespace roomcad {
namespace {

Report sample_report() {
  Report r;
  Diagnostic overlap;
  overlap.code = Code::wall_overlap;
  overlap.objects = {"a", "b"};
  overlap.message = "walls \"a\" and \"b\" overlap";
  overlap.fix = "move wall \"b\" 0.1 m east";
  overlap.where = Where{{1, 2.5}, Point2{3, 4}};
  r.add(overlap);
  Diagnostic parse;
  parse.code = Code::parse_error;
  parse.message = "plan.json:3:7: /walls/0/thickness: expected a number, found \"x\"";
  parse.location = Location{"plan.json", "/walls/0/thickness", 3, 7};
  r.add(parse);
  Diagnostic door;
  door.severity = Severity::warning;
  door.code = Code::door_above_floor;
  door.objects = {"d\"1"};
  door.message = "door \"d1\" starts 0.2 m above the floor";
  door.where = Where{{0.1, -0.0}, std::nullopt};
  r.add(door);
  return r;
}

TEST(ReportFormat, JsonHasTheSpecsShape) {
  EXPECT_EQ(
      format_report_json(sample_report()),
      "{\n"
      "  \"ok\": false,\n"
      "  \"errors\": [\n"
      "    {\"code\": \"wall_overlap\", \"objects\": [\"a\", \"b\"], \"message\": \"walls "
      "\\\"a\\\" and "
      "\\\"b\\\" overlap\", \"where\": [[1.0, 2.5], [3.0, 4.0]], \"fix\": \"move wall \\\"b\\\" "
      "0.1 m east\"},\n"
      "    {\"code\": \"parse_error\", \"objects\": [], \"message\": \"plan.json:3:7: "
      "/walls/0/thickness: "
      "expected a number, found \\\"x\\\"\", \"file\": \"plan.json\", \"line\": 3, \"column\": 7, "
      "\"pointer\": \"/walls/0/thickness\"}\n"
      "  ],\n"
      "  \"warnings\": [\n"
      "    {\"code\": \"door_above_floor\", \"objects\": [\"d\\\"1\"], \"message\": \"door "
      "\\\"d1\\\" starts "
      "0.2 m above the floor\", \"where\": [0.1, -0.0]}\n"
      "  ]\n"
      "}\n");
}

TEST(ReportFormat, EmptyReportIsOk) {
  EXPECT_EQ(format_report_json(Report{}),
            "{\n  \"ok\": true,\n  \"errors\": [],\n  \"warnings\": []\n}\n");
  EXPECT_EQ(format_report_text(Report{}, true), "");
  EXPECT_EQ(format_report_summary(Report{}), "no problems");
}

TEST(ReportFormat, WarningsAloneAreOk) {
  Report r;
  Diagnostic w;
  w.severity = Severity::warning;
  w.code = Code::unknown_field;
  w.message = std::string("m");
  r.add(w);
  EXPECT_EQ(format_report_json(r).rfind("{\n  \"ok\": true,\n  \"errors\": [],\n", 0), 0u);
  EXPECT_EQ(format_report_summary(r), "0 errors, 1 warning");
}

TEST(ReportFormat, TextWithoutColour) {
  EXPECT_EQ(
      format_report_text(sample_report(), false),
      "error[wall_overlap] a, b: walls \"a\" and \"b\" overlap\n"
      "  at: (1, 2.5) .. (3, 4) m\n"
      "  fix: move wall \"b\" 0.1 m east\n"
      "error[parse_error]: plan.json:3:7: /walls/0/thickness: expected a number, found \"x\"\n"
      "warning[door_above_floor] d\"1: door \"d1\" starts 0.2 m above the floor\n"
      "  at: (0.1, 0) m\n");
  EXPECT_EQ(format_report_summary(sample_report()), "2 errors, 1 warning");
}

TEST(ReportFormat, TextRoundsPlacesToTenDigitsButKeepsTinyOnes) {
  Report r;
  Diagnostic d;
  d.code = Code::wall_overlap;
  d.message = std::string("m");
  d.where = Where{{7.859999999999999, 1e-7}, Point2{-2.0000000000000004, 123456.789}};
  r.add(d);
  EXPECT_NE(format_report_text(r, false).find("  at: (7.86, 1e-07) .. (-2, 123456.789) m\n"),
            std::string::npos);
  EXPECT_NE(format_report_json(r).find("7.859999999999999"), std::string::npos);
}

TEST(ReportFormat, TextWithColourOnlyAddsEscapes) {
  const std::string coloured = format_report_text(sample_report(), true);
  EXPECT_NE(coloured.find("\033[1;31merror\033[0m"), std::string::npos);
  EXPECT_NE(coloured.find("\033[1;33mwarning\033[0m"), std::string::npos);
  std::string stripped;
  for (std::size_t i = 0; i < coloured.size(); ++i) {
    if (coloured[i] == '\033') {
      i = coloured.find('m', i);
      continue;
    }
    stripped += coloured[i];
  }
  EXPECT_EQ(stripped, format_report_text(sample_report(), false));
  EXPECT_EQ(format_report_text(sample_report(), false).find('\033'), std::string::npos);
}

/// A rule finding whose fix is two edits.
Report finding_with_edits() {
  Report r;
  Diagnostic d;
  d.severity = Severity::warning;
  d.code = Code::door_swing_blocked;
  d.objects = {"d1", "w 2"};
  d.message = "door 'd1' cannot open fully";
  d.fix = "swing it out";
  FixEdit set;
  set.id = "d1";
  set.fields = {{"swing", "out"}, {"offset", "1.25"}};
  FixEdit rm;
  rm.op = FixEdit::Op::remove;
  rm.id = "w 2";
  rm.cascade = true;
  d.edits = {set, rm};
  r.add(d);
  return r;
}

TEST(ReportFormat, FixEditsArePrintedAsCommandsInTextAndJson) {
  ReportFormatOptions o;
  o.plan_file = "my plan.json";
  EXPECT_EQ(format_report_text(finding_with_edits(), false, o),
            "warning[door_swing_blocked] d1, w 2: door 'd1' cannot open fully\n"
            "  fix: swing it out\n"
            "  edit: roomcad set 'my plan.json' d1 swing=out offset=1.25\n"
            "  edit: roomcad rm 'my plan.json' 'w 2' --cascade\n");
  const std::string json = format_report_json(finding_with_edits(), o);
  EXPECT_NE(json.find("\"edits\": [{\"op\": \"set\", \"id\": \"d1\", \"fields\": {\"swing\": "
                      "\"out\", \"offset\": "
                      "\"1.25\"}, \"command\": \"roomcad set 'my plan.json' d1 swing=out "
                      "offset=1.25\"}, {\"op\": \"rm\", "
                      "\"id\": \"w 2\", \"cascade\": true, "),
            std::string::npos)
      << json;
}

TEST(ReportFormat, BaselineComparisonMarksItemsAndListsTheFixed) {
  Report old_report = sample_report();
  const Report current = finding_with_edits();
  const ReportComparison c = compare_reports(old_report, current);
  ReportFormatOptions o;
  o.comparison = &c;
  o.baseline_file = "old.json";
  const std::string text = format_report_text(current, false, o);
  EXPECT_EQ(text.rfind("new warning[door_swing_blocked]", 0), 0u) << text;
  EXPECT_NE(text.find("fixed since old.json:\nfixed error[wall_overlap] a, b:"), std::string::npos)
      << text;
  EXPECT_EQ(format_report_summary(current, o),
            "0 errors, 1 warning; against old.json: 1 new, 0 unchanged, 3 fixed");
  const std::string json = format_report_json(current, o);
  EXPECT_NE(json.find("{\"id\": \"door_swing_blocked:d1+w 2\", \"status\": \"new\", \"code\""),
            std::string::npos)
      << json;
  EXPECT_NE(
      json.find(
          "\"baseline\": {\"file\": \"old.json\", \"new\": 1, \"unchanged\": 0, \"fixed\": [\n"
          "      {\"id\": \"wall_overlap:a+b\", \"code\": \"wall_overlap\""),
      std::string::npos)
      << json;
}

}  // namespace
}  // namespace roomcad
