// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>

#include "geometry/rooms.h"
#include "io/detail/ifc_shapes.h"
#include "io/ifc_export.h"
#include "io/step_file.h"
#include "mesh/mesh_check.h"
#include "plan/arc_chords.h"
#include "plan/plan_levels.h"
#include "solid/analytic_volume.h"

namespace roomcad {
namespace {

// Two rooms side by side on two levels: a T (the middle wall stops on the outer ones), mitred
// corners, a door, a window and a slab.
Plan two_storeys() {
  Plan plan;
  plan.site.max_height = 9.0;
  plan.levels = {{.id = "ground", .elevation = 0.0, .height = 3.0},
                 {.id = "first", .elevation = 3.0, .height = 2.6}};
  auto wall = [&](const char* id, Point2 a, Point2 b, const char* level) {
    Wall& w = plan.walls.emplace_back();
    w.id = id, w.from = a, w.to = b, w.level = level;
  };
  wall("south", {1, 1}, {11, 1}, "ground");
  wall("east", {11, 1}, {11, 7}, "ground");
  wall("north", {11, 7}, {1, 7}, "ground");
  wall("west", {1, 7}, {1, 1}, "ground");
  wall("mid", {6, 1}, {6, 7}, "ground");
  wall("upper", {1, 4}, {11, 4}, "first");
  plan.openings.push_back({.id = "entry",
                           .type = OpeningType::door,
                           .wall = "south",
                           .offset = 1.5,
                           .width = 0.9,
                           .height = 2.1});
  plan.openings.push_back({.id = "win",
                           .type = OpeningType::window,
                           .wall = "north",
                           .offset = 2,
                           .width = 1.4,
                           .height = 1.3,
                           .sill = 0.9});
  plan.slabs.push_back({.id = "floor1",
                        .level = "first",
                        .outline = {{1, 1}, {11, 1}, {11, 7}, {1, 7}},
                        .top = 0.0,
                        .thickness = 0.2});
  return plan;
}

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
    ++n;
  return n;
}

TEST(IfcExport, WritesTheSpatialTreeAndEveryObjectOnce) {
  IfcExportSummary summary;
  const Result<std::string> ifc = format_ifc(two_storeys(), "two.ifc", &summary);
  ASSERT_TRUE(ifc.ok()) << ifc.error();
  const std::string& t = ifc.value();
  EXPECT_TRUE(t.starts_with("ISO-10303-21;\n"));
  EXPECT_NE(t.find("FILE_SCHEMA(('IFC4'));"), std::string::npos);
  EXPECT_EQ(count(t, "=IFCPROJECT("), 1u);
  EXPECT_EQ(count(t, "=IFCBUILDINGSTOREY("), 2u);
  EXPECT_EQ(count(t, "=IFCWALL("), 6u);
  EXPECT_EQ(count(t, "=IFCOPENINGELEMENT("), 2u);
  EXPECT_EQ(count(t, "=IFCRELVOIDSELEMENT("), 2u);
  EXPECT_EQ(count(t, "=IFCRELFILLSELEMENT("), 2u);
  EXPECT_EQ(count(t, "=IFCDOOR("), 1u);
  EXPECT_EQ(count(t, "=IFCWINDOW("), 1u);
  EXPECT_EQ(count(t, "=IFCSLAB("), 1u);
  const Plan plan = two_storeys();
  const std::size_t rooms = find_rooms(plan_of_level(plan, "ground")).size() +
                            find_rooms(plan_of_level(plan, "first")).size();
  EXPECT_EQ(find_rooms(plan_of_level(plan, "ground")).size(),
            2u);  // the two rooms of the ground floor
  EXPECT_EQ(count(t, "=IFCSPACE("), rooms);
  EXPECT_EQ(count(t, "=IFCSURFACESTYLE("), 3u);  // the walls', the slab's and the floor's (spaces)
  EXPECT_EQ(count(t, "=IFCSIUNIT(*,.LENGTHUNIT.,$,.METRE.)"), 1u);
  EXPECT_EQ(summary.walls, 6u);
  EXPECT_EQ(summary.doors, 1u);
  EXPECT_EQ(summary.spaces, rooms);
  // Each instance parses back, and every GlobalId is distinct.
  const Result<step::File> parsed = step::parse(t, "two.ifc");
  ASSERT_TRUE(parsed.ok()) << parsed.error();
  std::set<std::string> ids;
  std::size_t roots = 0;
  for (const step::Instance& e : parsed.value().instances) {
    if (e.parameters.empty() || e.parameters[0].kind != step::Value::Kind::string ||
        e.parameters[0].text.size() != 22)
      continue;
    ++roots;
    ids.insert(e.parameters[0].text);
  }
  EXPECT_GT(roots, 20u);
  EXPECT_EQ(ids.size(), roots);
}

TEST(IfcExport, SamePlanGivesTheSameBytesAndIdsGiveTheGlobalIds) {
  const Plan plan = two_storeys();
  EXPECT_EQ(format_ifc(plan, "a.ifc").value(), format_ifc(plan, "a.ifc").value());
  Plan renamed = plan;
  renamed.walls[0].id = "south2";
  renamed.openings[0].wall = "south2";
  const std::string a = format_ifc(plan, "a.ifc").value();
  const std::string b = format_ifc(renamed, "a.ifc").value();
  const std::regex wall(R"(=IFCWALL\('([^']{22})')");
  std::smatch ma, mb;
  ASSERT_TRUE(std::regex_search(a, ma, wall));
  ASSERT_TRUE(std::regex_search(b, mb, wall));
  EXPECT_NE(ma[1], mb[1]);
}

// Joined walls' bodies do not overlap: at the T the middle wall stops at the outer walls' inner
// faces, the corners are mitred, so the bodies' volumes add up to the united solid's.
TEST(IfcExport, WallBodiesAddUpToTheUnitedSolid) {
  Plan plan = two_storeys();
  plan.levels.clear(), plan.slabs.clear(), plan.openings.clear();
  plan.walls.pop_back();
  for (Wall& w : plan.walls) w.level.clear();
  const Joins joins = find_joins(plan);
  const io_detail::JoinedWalls joined(plan, joins);
  double volume = 0.0;
  for (std::size_t i = 0; i < plan.walls.size(); ++i) {
    const auto f = io_detail::export_footprint(joined, i);
    double area = 0.0;
    for (std::size_t k = 0; k < 4; ++k)
      area += f[k].x * f[(k + 1) % 4].y - f[(k + 1) % 4].x * f[k].y;
    EXPECT_GT(area, 0.0) << plan.walls[i].id;  // counter-clockwise
    volume += area / 2 * plan.walls[i].height;
  }
  EXPECT_NEAR(volume, analytic_wall_volume(plan), 1e-12 * volume);
  const auto mid = io_detail::export_footprint(joined, 4);
  EXPECT_DOUBLE_EQ(mid[0].y, 1.125);  // the south wall's inner face
  EXPECT_DOUBLE_EQ(mid[1].y, 6.875);  // the north wall's
}

TEST(IfcExport, SlopedWallIsAClosedFaceSet) {
  Plan plan = two_storeys();
  plan.walls[5].height_at_end = 1.5;
  const std::string t = format_ifc(plan, "a.ifc").value();
  EXPECT_EQ(count(t, "=IFCTRIANGULATEDFACESET("), 1u);
  EXPECT_NE(t.find(",$,.T.,((1,3,2),(1,4,3),(5,6,7),(5,7,8)"), std::string::npos);
}

TEST(IfcExport, ArcWallIsItsChordsWithItsOpeningCutChordByChord) {
  Plan plan = two_storeys();
  plan.walls[2].arc_extent = 30.0;  // north bows out; its window spans chords
  plan.site.chord_tolerance = 0.01;
  const std::size_t chords = chord_polyline(plan.walls[2], 0.01).size() - 1;
  ASSERT_GE(chords, 3u);
  IfcExportSummary summary;
  const std::string t = format_ifc(plan, "a.ifc", &summary).value();
  EXPECT_EQ(summary.walls, 6u);
  EXPECT_EQ(count(t, "=IFCWALL("), 6u);
  // The axis: a polyline through the chord corners; the body: one extrusion per chord.
  const std::regex axis("IFCSHAPEREPRESENTATION\\(#\\d+,'Axis','Curve2D',\\(#(\\d+)\\)\\)");
  std::size_t longest = 0;
  for (auto it = std::sregex_iterator(t.begin(), t.end(), axis); it != std::sregex_iterator();
       ++it) {
    const std::string line = "#" + (*it)[1].str() + "=IFCPOLYLINE((";
    const std::size_t at = t.find(line);
    ASSERT_NE(at, std::string::npos);
    longest = std::max(longest, count(t.substr(at, t.find('\n', at) - at), "#") - 1);
  }
  EXPECT_EQ(longest, chords + 1);
  const std::regex body("'Body','SweptSolid',\\(((#\\d+,?)+)\\)");
  std::size_t items = 0;
  for (auto it = std::sregex_iterator(t.begin(), t.end(), body); it != std::sregex_iterator(); ++it)
    items = std::max(items, count((*it)[1].str(), "#"));
  EXPECT_EQ(items, chords);
  // A shape would have to bend around the arc: refused, naming the opening and the wall.
  plan.openings[1].shape = {{0, 0}, {1, 0}, {0.5, 1}};
  const Result<std::string> shaped = format_ifc(plan, "a.ifc");
  ASSERT_FALSE(shaped.ok());
  EXPECT_EQ(shaped.error().code, Code::unsupported);
  EXPECT_NE(shaped.error().message.find("\"win\""), std::string::npos);
  EXPECT_NE(shaped.error().message.find("\"north\""), std::string::npos);
}

TEST(StepFile, RealsAndStringsAreWrittenAsTheStandardSays) {
  std::string out;
  for (const double x : {3.0, 0.25, -0.0, 1e-5, 1.5e20, -2.0}) {
    step::append_real(out, x);
    out += ' ';
  }
  EXPECT_EQ(out, "3. 0.25 0. 1.E-05 1.5E+20 -2. ");
  out.clear();
  step::append_string(out,
                      "it's a\\b K\xc3\xbc"
                      "che \xf0\x9f\x8f\xa0");
  EXPECT_EQ(out, "'it''s a\\\\b K\\X2\\00FC\\X0\\che \\X2\\D83CDFE0\\X0\\'");
  const std::string file =
      "ISO-10303-21;HEADER;FILE_SCHEMA(('IFC4'));ENDSEC;DATA;#1=IFCLABEL(" + out +
      ");\n/* a comment */ "
      "#2=X((1.,-2.5E-3,+4),$,*,.T.,IFCLENGTHMEASURE(2.),#1);ENDSEC;END-ISO-10303-21;";
  const Result<step::File> parsed = step::parse(file, "f.ifc");
  ASSERT_TRUE(parsed.ok()) << parsed.error();
  EXPECT_EQ(parsed.value().schema, "IFC4");
  EXPECT_EQ(parsed.value().find(1)->parameters[0].text,
            "it's a\\b K\xc3\xbc"
            "che \xf0\x9f\x8f\xa0");
  const auto& p = parsed.value().find(2)->parameters;
  ASSERT_EQ(p.size(), 6u);
  EXPECT_EQ(p[0].items[1].number, -2.5e-3);
  EXPECT_EQ(p[0].items[2].kind, step::Value::Kind::integer);
  EXPECT_EQ(p[1].kind, step::Value::Kind::null);
  EXPECT_EQ(p[2].kind, step::Value::Kind::derived);
  EXPECT_EQ(p[3].text, "T");
  EXPECT_EQ(p[4].text, "IFCLENGTHMEASURE");
  EXPECT_EQ(p[5].id, 1u);
}

TEST(StepFile, StringsAreAlwaysReadAsUtf8) {
  // STEP allows only ASCII between quotes; exporters write raw UTF-8 (kept), raw Latin-1 (read
  // as such) and unpaired UTF-16 surrogates (U+FFFD), and a plan must hold UTF-8 only.
  const std::string file =
      "ISO-10303-21;HEADER;FILE_SCHEMA(('IFC2X3'));ENDSEC;DATA;"
      "#1=IFCLABEL('K\xc3\xbc"
      "che');#2=IFCLABEL('K\xfc"
      "che');"
      "#3=IFCLABEL('a\\X2\\D83C0041\\X0\\b');ENDSEC;END-ISO-10303-21;";
  const Result<step::File> parsed = step::parse(file, "names.ifc");
  ASSERT_TRUE(parsed.ok()) << parsed.error();
  EXPECT_EQ(parsed.value().find(1)->parameters[0].text,
            "K\xc3\xbc"
            "che");
  EXPECT_EQ(parsed.value().find(2)->parameters[0].text,
            "K\xc3\xbc"
            "che");
  EXPECT_EQ(parsed.value().find(3)->parameters[0].text,
            "a\xef\xbf\xbd"
            "Ab");
}

TEST(StepFile, MalformedTextIsAParseErrorNamingTheLine) {
  for (const char* text : {"not a step file", "ISO-10303-21;HEADER;ENDSEC;DATA;\n#1=A('open);",
                           "ISO-10303-21;HEADER;ENDSEC;DATA;\n#1=A(1);\n#1=B(2);ENDSEC;",
                           "ISO-10303-21;HEADER;ENDSEC;DATA;\n\n#1=A((((((((((((((((((((((((((((((("
                           "((((((((((((((((((((((((((((((((((((1))))))))))))))))))))))))))))))))))"
                           ")))))))))))))))))))))))))))))))))));ENDSEC;"}) {
    const Result<step::File> parsed = step::parse(text, "bad.ifc");
    ASSERT_FALSE(parsed.ok()) << text;
    EXPECT_EQ(parsed.error().code, Code::parse_error);
    EXPECT_NE(parsed.error().message.find("bad.ifc: line "), std::string::npos)
        << parsed.error().message;
  }
  EXPECT_NE(step::parse("ISO-10303-21;HEADER;ENDSEC;DATA;\n#1=A(1);\n#1=B(2);ENDSEC;", "bad.ifc")
                .error()
                .message.find("line 3: instance #1 is defined twice"),
            std::string::npos);
}

}  // namespace
}  // namespace roomcad
