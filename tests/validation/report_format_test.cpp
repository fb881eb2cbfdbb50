// Printing reports: the spec's JSON object and the text for people.
#include <string>

#include <gtest/gtest.h>

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
  EXPECT_EQ(format_report_json(sample_report()),
            "{\n"
            "  \"ok\": false,\n"
            "  \"errors\": [\n"
            "    {\"code\": \"wall_overlap\", \"objects\": [\"a\", \"b\"], \"message\": \"walls \\\"a\\\" and "
            "\\\"b\\\" overlap\", \"where\": [[1.0, 2.5], [3.0, 4.0]], \"fix\": \"move wall \\\"b\\\" 0.1 m east\"},\n"
            "    {\"code\": \"parse_error\", \"objects\": [], \"message\": \"plan.json:3:7: /walls/0/thickness: "
            "expected a number, found \\\"x\\\"\", \"file\": \"plan.json\", \"line\": 3, \"column\": 7, "
            "\"pointer\": \"/walls/0/thickness\"}\n"
            "  ],\n"
            "  \"warnings\": [\n"
            "    {\"code\": \"door_above_floor\", \"objects\": [\"d\\\"1\"], \"message\": \"door \\\"d1\\\" starts "
            "0.2 m above the floor\", \"where\": [0.1, -0.0]}\n"
            "  ]\n"
            "}\n");
}

TEST(ReportFormat, EmptyReportIsOk) {
  EXPECT_EQ(format_report_json(Report{}), "{\n  \"ok\": true,\n  \"errors\": [],\n  \"warnings\": []\n}\n");
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
  EXPECT_EQ(format_report_text(sample_report(), false),
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

}  // namespace
}  // namespace roomcad
