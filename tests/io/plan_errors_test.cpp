// SPDX-License-Identifier: GPL-3.0-or-later
// Reading bad plans: every problem found, with file, line, column and JSON pointer; no crash.
#include <string>

#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "plan_test_support.h"
#include "support/plan_reading.h"

namespace roomcad {
namespace {

using test::expect_one_error;

TEST(PlanErrors, NotJson) {
  expect_one_error("roomcad", {Code::parse_error, "", 1, 1, "syntax error"});
  expect_one_error("{\"walls\": [1, 2,]}", {Code::parse_error, "", 1, 17, "syntax error"});
  expect_one_error("{\"a\" 1}", {Code::parse_error, "", 1, 6, "expected ':'"});
  expect_one_error("{\n  'walls': []\n}", {Code::parse_error, "", 2, 3, "syntax error"});
  expect_one_error("{} {}", {Code::parse_error, "", 1, 4, "syntax error"});
  expect_one_error("{\"a\": NaN}", {Code::parse_error, "", 1, 7, "syntax error"});
  expect_one_error("{\"a\": \"\xff\"}", {Code::parse_error, "", 1, 8, "UTF-8"});
  expect_one_error("// comment\n{}", {Code::parse_error, "", 1, 1, "syntax error"});
}

TEST(PlanErrors, EmptyAndTruncated) {
  expect_one_error("", {Code::parse_error, "", 1, 1, "unexpected end of input"});
  expect_one_error("  \n ", {Code::parse_error, "", 2, 2, "unexpected end of input"});
  const std::string full(test::kSpecExample);
  const std::string cut = full.substr(0, full.find("\"openings\""));
  expect_one_error(cut, {Code::parse_error, "", 11, 3, "unexpected end of input"});
  expect_one_error("{\"walls\": [{\"id\": \"a",
                   {Code::parse_error, "", 1, 21, "missing closing quote"});
}

TEST(PlanErrors, TopLevelMustBeAnObject) {
  expect_one_error("[]", {Code::parse_error, "", 1, 1,
                          "expected an object (a roomcad plan), found an empty array"});
  expect_one_error("\n 42", {Code::parse_error, "", 2, 2, "found 42"});
  expect_one_error("null", {Code::parse_error, "", 1, 1, "found null"});
}

TEST(PlanErrors, NumberTooLargeForADouble) {
  expect_one_error(
      "{\"walls\": [{\"id\": \"a\", \"from\": [0, 1e999], \"to\": [1, 0]}]}",
      {Code::invalid_value, "/walls/0/from/1", 1, 36, "1e999 is too large for a double"});
  expect_one_error("{\"site\": {\"max_height\":\n  -2e400}}",
                   {Code::invalid_value, "/site/max_height", 2, 3, "-2e400"});
  expect_one_error("[1e999]", {Code::invalid_value, "/0", 1, 2, "too large"});
}

TEST(PlanErrors, DuplicateKey) {
  expect_one_error("{\"site\": {\"cell_size\": 1,\n \"cell_size\": 2}}",
                   {Code::parse_error, "/site/cell_size", 2, 2, "duplicate key \"cell_size\""});
  expect_one_error("{\"walls\": [], \"walls\": []}",
                   {Code::parse_error, "/walls", 1, 15, "duplicate key"});
}

TEST(PlanErrors, NestingTooDeepIsAnErrorNotACrash) {
  const std::string deep = "{\"x\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  const test::PlanReading r = test::read_plan(deep, "plan.json");
  EXPECT_FALSE(r.plan.has_value());
  ASSERT_EQ(r.report.items.size(), 1u);
  EXPECT_EQ(r.report.items[0].code, Code::parse_error);
  EXPECT_NE(r.report.items[0].message.find("nesting deeper"), std::string::npos);
}

TEST(PlanErrors, WrongTypeOfEveryKindOfField) {
  // number
  expect_one_error(
      R"({"walls": [{"id": "a", "from": [0, 0], "to": [1, 0], "thickness": "thick"}]})",
      {Code::parse_error, "/walls/0/thickness", 1, 67, "expected a number, found \"thick\""});
  expect_one_error(R"({"site": {"cell_size": null}})",
                   {Code::parse_error, "/site/cell_size", 1, 24, "found null"});
  expect_one_error(
      R"({"lights": [{"id": "l", "intensity": true}]})",
      {Code::parse_error, "/lights/0/intensity", 1, 38, "expected a number, found true"});
  expect_one_error(
      R"({"cameras": [{"id": "c", "eye": [0, 0, 1], "target": [0, 0, 0], "fov_deg": {}}]})",
      {Code::parse_error, "/cameras/0/fov_deg", 1, 76, "found an object"});
  // point, vector
  expect_one_error(R"({"walls": [{"id": "a", "from": [0, 0, 0], "to": [1, 0]}]})",
                   {Code::parse_error, "/walls/0/from", 1, 32,
                    "expected an array of 2 numbers [x, y], found an array of 3 items"});
  expect_one_error(R"({"walls": [{"id": "a", "from": [0, "0"], "to": [1, 0]}]})",
                   {Code::parse_error, "/walls/0/from/1", 1, 36, "expected a number, found \"0\""});
  expect_one_error(R"({"site": {"origin": 5}})",
                   {Code::parse_error, "/site/origin", 1, 21, "found 5"});
  expect_one_error(R"({"lights": [{"id": "l", "direction": [1, 2]}]})",
                   {Code::parse_error, "/lights/0/direction", 1, 38,
                    "an array of 3 numbers [x, y, z], found an array of 2 items"});
  expect_one_error(
      R"({"cameras": [{"id": "c", "eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 0, false]}]})",
      {Code::parse_error, "/cameras/0/up/2", 1, 78, "found false"});
  // string ids and references
  expect_one_error(R"({"walls": [{"id": 7, "from": [0, 0], "to": [1, 0]}]})",
                   {Code::parse_error, "/walls/0/id", 1, 19, "expected a string id, found 7"});
  expect_one_error(R"({"openings": [{"id": "o", "wall": ["a"], "offset": 1}]})",
                   {Code::parse_error, "/openings/0/wall", 1, 35,
                    "expected a string id, found an array of 1 item"});
  expect_one_error(R"({"lights": [{"id": null}]})",
                   {Code::parse_error, "/lights/0/id", 1, 20, "found null"});
  expect_one_error(R"({"cameras": [{"id": 1.5, "eye": [0, 0, 1], "target": [0, 0, 0]}]})",
                   {Code::parse_error, "/cameras/0/id", 1, 21, "found 1.5"});
  // enums and colours given as something else than a string
  expect_one_error(
      R"({"openings": [{"id": "o", "wall": "a", "offset": 1, "type": 1}]})",
      {Code::parse_error, "/openings/0/type", 1, 61, "expected \"door\" or \"window\", found 1"});
  expect_one_error(
      R"({"site": {"floor_color": 13158600}})",
      {Code::parse_error, "/site/floor_color", 1, 26, "colour string \"#rrggbb\", found 13158600"});
  // sections and their items
  expect_one_error(R"({"walls": {}})",
                   {Code::parse_error, "/walls", 1, 11, "expected an array, found an object"});
  expect_one_error(R"({"site": []})",
                   {Code::parse_error, "/site", 1, 10, "expected an object, found an empty array"});
  expect_one_error(R"({"cameras": ["c"]})",
                   {Code::parse_error, "/cameras/0", 1, 14, "expected an object, found \"c\""});
  // format, version, units
  expect_one_error(R"({"format": 1})",
                   {Code::parse_error, "/format", 1, 12, "expected the string \"roomcad-plan\""});
  expect_one_error(R"({"version": "1"})", {Code::parse_error, "/version", 1, 13,
                                           "expected the number 1 or 2, found \"1\""});
  expect_one_error(R"({"units": ["m"]})",
                   {Code::parse_error, "/units", 1, 11, "expected \"m\", \"cm\" or \"mm\""});
}

TEST(PlanErrors, CellsArePositiveIntegers) {
  expect_one_error(R"({"site": {"cells": [12]}})",
                   {Code::parse_error, "/site/cells", 1, 20, "2 positive integers"});
  expect_one_error(R"({"site": {"cells": [12, 2.5]}})", {Code::parse_error, "/site/cells/1", 1, 25,
                                                         "expected a positive integer, found 2.5"});
  expect_one_error(R"({"site": {"cells": ["12", 8]}})",
                   {Code::parse_error, "/site/cells/0", 1, 21, "found \"12\""});
  expect_one_error(R"({"site": {"cells": [0, 8]}})",
                   {Code::invalid_value, "/site/cells/0", 1, 21, "found 0"});
  expect_one_error(R"({"site": {"cells": [4, -3]}})",
                   {Code::invalid_value, "/site/cells/1", 1, 24, "found -3"});
  expect_one_error(R"({"site": {"cells": [4, 18446744073709551615]}})",
                   {Code::invalid_value, "/site/cells/1", 1, 24, "too large"});
  EXPECT_EQ(test::read_ok(R"({"site": {"cells": [12.0, 1e2]}})").site.cells,
            (std::array<std::int64_t, 2>{12, 100}));
}

TEST(PlanErrors, UnknownEnumValues) {
  expect_one_error(R"({"openings": [{"id": "o", "wall": "a", "offset": 1, "type": "hatch"}]})",
                   {Code::invalid_value, "/openings/0/type", 1, 61,
                    "unknown value \"hatch\"; expected \"door\" or \"window\""});
  expect_one_error(
      R"({"openings": [{"id": "o", "wall": "a", "offset": 1, "hinge": "top"}]})",
      {Code::invalid_value, "/openings/0/hinge", 1, 62, "expected \"left\" or \"right\""});
  expect_one_error(R"({"openings": [{"id": "o", "wall": "a", "offset": 1, "swing": "In"}]})",
                   {Code::invalid_value, "/openings/0/swing", 1, 62, "expected \"in\" or \"out\""});
  expect_one_error(R"({"lights": [{"id": "l", "type": "point"}]})",
                   {Code::invalid_value, "/lights/0/type", 1, 33, "expected \"directional\""});
  expect_one_error(
      R"({"cameras": [{"id": "c", "eye": [0, 0, 1], "target": [0, 0, 0], "projection": "fisheye"}]})",
      {Code::invalid_value, "/cameras/0/projection", 1, 79,
       "expected \"perspective\" or \"orthographic\""});
}

TEST(PlanErrors, BadColours) {
  for (const char* colour : {"red", "#fff", "#12345g", "c8c8c8", "#c8c8c8 ", ""}) {
    expect_one_error(
        std::string(R"({"walls": [{"id": "a", "from": [0, 0], "to": [1, 0], "color": ")") + colour +
            "\"}]}",
        {Code::invalid_value, "/walls/0/color", 1, 63, "expected a colour \"#rrggbb\""});
  }
}

TEST(PlanErrors, UnsupportedFormatVersionUnits) {
  expect_one_error(R"({"format": "roomcad"})",
                   {Code::invalid_value, "/format", 1, 12, "unsupported format \"roomcad\""});
  expect_one_error(R"({"version": 3})",
                   {Code::invalid_value, "/version", 1, 13, "unsupported version 3"});
  expect_one_error(R"({"version": 1.5})",
                   {Code::invalid_value, "/version", 1, 13, "unsupported version 1.5"});
  expect_one_error(R"({"units": "ft"})",
                   {Code::invalid_value, "/units", 1, 11, "unsupported units \"ft\""});
  expect_one_error(R"({"units": "M"})",
                   {Code::invalid_value, "/units", 1, 11, "unsupported units \"M\""});
}

TEST(PlanErrors, MissingRequiredFields) {
  expect_one_error(R"({"walls": [{"from": [0, 0], "to": [1, 0]}]})",
                   {Code::parse_error, "/walls/0", 1, 12, "missing required field \"id\""});
  expect_one_error(R"({"walls": [{"id": "a", "to": [1, 0]}]})",
                   {Code::parse_error, "/walls/0", 1, 12, "missing required field \"from\""});
  expect_one_error(R"({"walls": [{"id": "a", "from": [1, 0]}]})",
                   {Code::parse_error, "/walls/0", 1, 12, "missing required field \"to\""});
  expect_one_error(R"({"openings": [{"id": "o", "offset": 1}]})",
                   {Code::parse_error, "/openings/0", 1, 15, "missing required field \"wall\""});
  expect_one_error(R"({"openings": [{"id": "o", "wall": "a"}]})",
                   {Code::parse_error, "/openings/0", 1, 15, "missing required field \"offset\""});
  expect_one_error(R"({"lights": [{}]})",
                   {Code::parse_error, "/lights/0", 1, 13, "missing required field \"id\""});
  expect_one_error(R"({"cameras": [{"id": "c", "target": [0, 0, 0]}]})",
                   {Code::parse_error, "/cameras/0", 1, 14, "missing required field \"eye\""});
  expect_one_error(R"({"cameras": [{"id": "c", "eye": [0, 0, 0]}]})",
                   {Code::parse_error, "/cameras/0", 1, 14, "missing required field \"target\""});
}

TEST(PlanErrors, ObjectIdsAreNamedWhenKnown) {
  const test::PlanReading r = test::read_plan(
      R"({"walls": [{"id": "north", "from": [0, 0], "to": [1, 0], "height": "tall"}]})", "p.json");
  ASSERT_EQ(r.report.items.size(), 1u);
  EXPECT_EQ(r.report.items[0].objects, std::vector<std::string>{"north"});
  EXPECT_EQ(r.report.items[0].message,
            "p.json:1:68: /walls/0/height: expected a number, found \"tall\"");
}

TEST(PlanErrors, EveryProblemInOnePassInFileOrder) {
  const char* text = R"({
  "format": "roomcad-plan", "version": 3, "units": "yd",
  "site": {"cells": [0, 2.5], "floor_color": "red", "colour": "#ffffff"},
  "walls": [
    {"id": 7, "from": [0, 0], "to": [1, "x"], "thickness": "thick", "heigth": 3},
    {"from": [0, 0, 0]},
    5
  ],
  "openings": [{"id": "d", "type": "hatch", "wall": "w", "offset": 1, "hinge": "up"}],
  "cameras": [{"id": "c", "projection": "fisheye", "eye": [0, 0, 0], "target": [1, 1, true]}],
  "notes": {"b": 1}
})";
  const test::PlanReading r = test::read_plan(text, "plan.json");
  EXPECT_FALSE(r.plan.has_value());
  std::vector<std::string> found;
  for (const Diagnostic& d : r.report.items)
    found.push_back(std::string(to_string(d.code)) + ' ' + d.location->pointer + ' ' +
                    std::to_string(d.location->line));
  const std::vector<std::string> expected = {"invalid_value /version 2",
                                             "invalid_value /units 2",
                                             "invalid_value /site/cells/0 3",
                                             "parse_error /site/cells/1 3",
                                             "invalid_value /site/floor_color 3",
                                             "unknown_field /site/colour 3",
                                             "parse_error /walls/0/id 5",
                                             "parse_error /walls/0/to/1 5",
                                             "parse_error /walls/0/thickness 5",
                                             "unknown_field /walls/0/heigth 5",
                                             "parse_error /walls/1 6",
                                             "parse_error /walls/1 6",
                                             "parse_error /walls/1/from 6",
                                             "parse_error /walls/2 7",
                                             "invalid_value /openings/0/type 9",
                                             "invalid_value /openings/0/hinge 9",
                                             "invalid_value /cameras/0/projection 10",
                                             "parse_error /cameras/0/target/2 10",
                                             "unknown_field /notes 11"};
  EXPECT_EQ(found, expected);
  EXPECT_EQ(r.report.error_count(), 16u);
  EXPECT_EQ(r.report.warning_count(), 3u);
}

TEST(PlanErrors, UnknownFieldsAreWarningsAndKept) {
  const char* text = R"({"units": "m", "zeta": [1, {"b": 2, "a": 0.50}], "alpha": "x",
  "site": {"colour": "#ffffff"},
  "walls": [{"id": "a", "from": [0, 0], "to": [1, 0], "heigth": 3, "note": null}],
  "openings": [{"id": "o", "wall": "a", "offset": 0, "glass": true}],
  "lights": [{"id": "l", "color": "#ffffff"}],
  "cameras": [{"id": "c", "eye": [0, 0, 1], "target": [0, 0, 0], "near": 0.1}]})";
  const test::PlanReading r = test::read_plan(text, "plan.json");
  ASSERT_TRUE(r.plan.has_value());
  EXPECT_TRUE(r.report.ok());
  std::vector<std::string> pointers;
  for (const Diagnostic& d : r.report.items) {
    EXPECT_EQ(d.severity, Severity::warning);
    EXPECT_EQ(d.code, Code::unknown_field);
    pointers.push_back(d.location->pointer);
  }
  EXPECT_EQ(pointers, (std::vector<std::string>{
                          "/zeta", "/alpha", "/site/colour", "/walls/0/heigth", "/walls/0/note",
                          "/openings/0/glass", "/lights/0/color", "/cameras/0/near"}));
  // The position is the key's.
  EXPECT_EQ(r.report.items[0].location->line, 1u);
  EXPECT_EQ(r.report.items[0].location->column, 16u);
  EXPECT_NE(r.report.items[3].message.find("did you mean \"height\"?"), std::string::npos);
  EXPECT_EQ(r.report.items[3].fix, "rename it to \"height\"");

  const Plan& p = *r.plan;
  EXPECT_EQ(p.extra, (ExtraFields{{"zeta", R"([1, {"a": 0.5, "b": 2}])"}, {"alpha", R"("x")"}}));
  EXPECT_EQ(p.site.extra, (ExtraFields{{"colour", R"("#ffffff")"}}));
  EXPECT_EQ(p.walls[0].extra, (ExtraFields{{"heigth", "3"}, {"note", "null"}}));
  EXPECT_EQ(p.openings[0].extra, (ExtraFields{{"glass", "true"}}));
  EXPECT_EQ(p.lights[0].extra, (ExtraFields{{"color", R"("#ffffff")"}}));
  EXPECT_EQ(p.cameras[0].extra, (ExtraFields{{"near", "0.1"}}));

  // Saving keeps them, sorted after the known fields.
  const std::string saved = write_plan_text(p);
  EXPECT_NE(saved.find(R"("color": "#e8e2d0", "heigth": 3, "note": null})"), std::string::npos)
      << saved;
  EXPECT_NE(saved.find("  \"cameras\": [\n"), std::string::npos);
  EXPECT_NE(saved.find("  ],\n  \"alpha\": \"x\",\n  \"zeta\": [1, {\"a\": 0.5, \"b\": 2}]\n}\n"),
            std::string::npos)
      << saved;
  const test::PlanReading again = test::read_plan(saved, "saved.json");
  ASSERT_TRUE(again.plan.has_value());
  EXPECT_EQ(again.report.warning_count(), 8u);
}

TEST(PlanErrors, PointersEscapeSlashAndTilde) {
  const test::PlanReading r = test::read_plan(R"({"a/b~c": 1})", "plan.json");
  ASSERT_EQ(r.report.items.size(), 1u);
  EXPECT_EQ(r.report.items[0].location->pointer, "/a~1b~0c");
}

TEST(PlanErrors, ColumnsCountCharactersNotBytes) {
  expect_one_error("{\"walls\": [{\"id\": \"é\", \"from\": 1, \"to\": [0, 0]}]}",
                   {Code::parse_error, "/walls/0/from", 1, 32, "expected an array of 2 numbers"});
}

TEST(PlanErrors, ByteOrderMarkIsSkipped) {
  EXPECT_EQ(test::read_ok("\xEF\xBB\xBF{\"site\": {}}"), Plan{});
  expect_one_error("\xEF\xBB\xBF{\"walls\": 1}",
                   {Code::parse_error, "/walls", 1, 12, "expected an array"});
  expect_one_error("\xEF\xBB\xBF[]", {Code::parse_error, "", 1, 2, "expected an object"});
}

// A document that is nearly all one "units" string: simdjson's string buffer holds each string
// once (5/3 of the document), and the reader once unescaped "units" twice (for the scale
// first, then to check it), running 100,000 bytes past it. Found by fuzz_plan_json under
// ASan as a corrupted heap block.
TEST(PlanErrors, AUnitsStringAsLongAsTheDocumentIsReadOnce) {
  expect_one_error("{\"units\": \"" + std::string(100000, 'y') + "\"}",
                   {Code::invalid_value, "/units", 1, 11,
                    "unsupported units \"" + std::string(39, 'y') + "...\""});
}

TEST(PlanErrors, LongStringsAreShortenedInMessages) {
  const std::string id(100, 'x');
  expect_one_error("{\"units\": \"" + std::string(60, 'y') + "\"}",
                   {Code::invalid_value, "/units", 1, 11,
                    "unsupported units \"" + std::string(39, 'y') + "...\""});
  const std::string accents =
      "{\"format\": \"" + std::string(38, 'a') + "\xC3\xA9\xC3\xA9\xC3\xA9\"}";
  const test::PlanReading r = test::read_plan(accents, "plan.json");
  ASSERT_EQ(r.report.items.size(), 1u);
  EXPECT_NE(r.report.items[0].message.find(std::string(38, 'a') + "...\""), std::string::npos)
      << r.report.items[0].message;
}

TEST(PlanErrors, NeverCrashOnMangledInput) {
  // Every prefix, and every single-byte change of the spec example, reads without crashing.
  const std::string text(test::kSpecExample);
  const std::string replacements = "{}[]\",:0-e.\\ \x01\xff";
  std::size_t failures = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    failures += !read_plan_text(text.substr(0, i), "cut.json").ok();
    for (char c : replacements) {
      std::string mangled = text;
      mangled[i] = c;
      const test::PlanReading r = test::read_plan(mangled, "mangled.json");
      EXPECT_EQ(r.plan.has_value(), r.report.ok());
      for (const Diagnostic& d : r.report.items) ASSERT_TRUE(d.location.has_value());
    }
  }
  EXPECT_EQ(failures, text.size() - 1);  // only the prefix without the final newline is a plan
}

}  // namespace
}  // namespace roomcad
