// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "import/ifc_import.h"
#include "io/ifc_export.h"
#include "io/plan_json.h"
#include "plan/plan_levels.h"
#include "support/run_command.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

std::filesystem::path model(const char* name) {
  return test::source_dir() / "examples" / "ifc" / name;
}

struct Expected {
  const char* file;
  std::size_t source_walls, walls_read, source_openings, openings_read, slabs_read, levels;
  std::size_t plan_walls;  ///< walls split where clipping planes meet count once each
};

// The bundled models (examples/ifc): the walls (curtain walls among them) and openings in the
// file, how many are read, and every element accounted for.
const Expected kModels[] = {
    {"IfcOpenHouse_IFC4.ifc", 4, 4, 4, 4, 0, 1, 6},
    {"duplex.ifc", 57, 56, 50, 38, 21, 4, 56},
    {"tested_sample_project.ifc", 4, 4, 10, 10, 2, 2, 4},
    {"bonsai_project0-openings.ifc", 5, 5, 4, 4, 0, 1, 5},
    {"sikongsphere_complex.ifc", 11, 11, 5, 5, 1, 2, 11},
    {"bimwhale_TallBuilding.ifc", 24, 24, 26, 26, 5, 5, 24},
};

TEST(IfcImport, RealModelsImportWithEveryLeftOutElementNamed) {
  for (const Expected& e : kModels) {
    SCOPED_TRACE(e.file);
    const Result<IfcImport> r = import_ifc_file(model(e.file));
    ASSERT_TRUE(r.ok()) << r.error();
    const IfcImport& i = r.value();
    const Plan& plan = i.plan;
    EXPECT_EQ(i.source_walls, e.source_walls);
    EXPECT_EQ(i.walls_read, e.walls_read);
    EXPECT_EQ(i.source_openings, e.source_openings);
    EXPECT_EQ(i.openings_read, e.openings_read);
    EXPECT_EQ(i.slabs_read, e.slabs_read);
    EXPECT_EQ(plan.slabs.size(), e.slabs_read);
    EXPECT_EQ(plan.levels.size(), e.levels);
    EXPECT_EQ(plan.walls.size(), e.plan_walls);
    std::size_t wall_warnings = 0, opening_warnings = 0, slab_warnings = 0;
    for (const Diagnostic& d : i.warnings.items) {
      EXPECT_EQ(d.severity, Severity::warning);
      EXPECT_TRUE(d.message.starts_with("#")) << d.message;  // names the entity
      const bool left_out = d.message.find("not imported") != std::string::npos;
      if (left_out && (d.message.find(" IFCWALL") != std::string::npos ||
                       d.message.find(" IFCCURTAINWALL") != std::string::npos))
        ++wall_warnings;
      if (left_out && d.message.find(" IFCOPENINGELEMENT") != std::string::npos) ++opening_warnings;
      if (left_out && d.message.find(" IFCSLAB") != std::string::npos) ++slab_warnings;
    }
    EXPECT_EQ(i.walls_read + wall_warnings, i.source_walls);
    EXPECT_EQ(i.openings_read + opening_warnings, i.source_openings);
    EXPECT_EQ(i.slabs_read + slab_warnings, i.source_slabs);
    // The tally holds the same: what is read and what is skipped, by entity type.
    std::size_t tallied_walls = 0, skipped_walls = 0;
    for (const auto& [type, t] : i.tally) {
      EXPECT_LE(t.approximated, t.read) << type;
      EXPECT_LE(t.unmeasured, t.approximated) << type;
      if (type.starts_with("IFCWALL") || type == "IFCCURTAINWALL")
        tallied_walls += t.read, skipped_walls += t.skipped;
    }
    EXPECT_EQ(tallied_walls + skipped_walls, i.source_walls);
    // It is a plan validation can judge: the format's checks pass, the findings are clashes.
    const Report report = validate(plan);
    for (const Diagnostic& d : report.items) {
      EXPECT_NE(d.code, Code::invalid_value) << d.message;
      EXPECT_NE(d.code, Code::unknown_reference) << d.message;
      EXPECT_NE(d.code, Code::duplicate_id) << d.message;
      EXPECT_NE(d.code, Code::out_of_bounds) << d.message;
    }
  }
}

// Each imported plan is written, validated and built (forced past its clashes) with the
// solid's check: the CLI as a user runs it.
TEST(IfcImport, RealModelsImportValidateAndBuildChecked) {
  const test::TempDir dir;
  for (const Expected& e : kModels) {
    SCOPED_TRACE(e.file);
    const std::string plan = (dir / (std::string(e.file) + ".json")).string();
    const auto imported = test::run_roomcad({"import", model(e.file).string(), "-o", plan});
    ASSERT_EQ(imported.status, 0) << imported.err;
    const std::string counts =
        std::to_string(e.walls_read) + " of " + std::to_string(e.source_walls) + " walls, " +
        std::to_string(e.openings_read) + " of " + std::to_string(e.source_openings) + " openings";
    EXPECT_NE(imported.err.find(counts), std::string::npos) << imported.err;
    const auto validated = test::run_roomcad({"validate", plan});
    EXPECT_LE(validated.status, 1) << validated.err;  // 1: clashes found, as in the file
    EXPECT_EQ(test::failure_code(validated), std::nullopt) << validated.err;
    const auto built = test::run_roomcad(
        {"build", plan, "--force", "--check", "-o", (dir / "model.obj").string()});
    EXPECT_EQ(built.status, 0) << built.err;
    EXPECT_NE((built.out + built.err).find("check: ok"), std::string::npos) << built.out;
  }
}

TEST(IfcImport, ClippedWallsTakeTheTopsOfTheirPlanes) {
  // IfcOpenHouse's gable walls: 3 m at the eaves, 5.5 m at the ridge, each split there.
  const Result<IfcImport> house = import_ifc_file(model("IfcOpenHouse_IFC4.ifc"));
  ASSERT_TRUE(house.ok()) << house.error();
  for (const char* id : {"East wall", "West wall"}) {
    SCOPED_TRACE(id);
    const Wall* eaves = find_wall(house.value().plan, id);
    const Wall* ridge = find_wall(house.value().plan, std::string(id) + " (2)");
    ASSERT_NE(eaves, nullptr);
    ASSERT_NE(ridge, nullptr);
    EXPECT_NEAR(eaves->height, 3.0, 1e-6);
    EXPECT_NEAR(eaves->height_at_end.value_or(0.0), 5.5, 1e-6);
    EXPECT_NEAR(ridge->height, 5.5, 1e-6);
    EXPECT_NEAR(ridge->height_at_end.value_or(0.0), 3.0, 1e-6);
    EXPECT_EQ(eaves->to, ridge->from);
  }
  // TallBuilding's walls are all clipped, by planes at their own tops and bottoms: read
  // exactly, with no approximation.
  const Result<IfcImport> tall = import_ifc_file(model("bimwhale_TallBuilding.ifc"));
  ASSERT_TRUE(tall.ok()) << tall.error();
  const IfcEntityTally& walls = tall.value().tally.at("IFCWALLSTANDARDCASE");
  EXPECT_EQ(walls.read, 24u);
  EXPECT_EQ(walls.approximated, 0u);
}

TEST(IfcImport, TheSiteSaysWhereTheModelStands) {
  // IfcSite RefLatitude (42, 21, 31, 181945), RefLongitude (-71, -3, -24, -263305): Boston.
  const Result<IfcImport> r = import_ifc_file(model("bimwhale_TallBuilding.ifc"));
  ASSERT_TRUE(r.ok()) << r.error();
  const auto& location = r.value().plan.site.location;
  ASSERT_TRUE(location.has_value());
  EXPECT_NEAR(location->latitude, 42 + 21 / 60.0 + 31.181945 / 3600, 1e-9);
  EXPECT_NEAR(location->longitude, -(71 + 3 / 60.0 + 24.263305 / 3600), 1e-9);
  EXPECT_EQ(location->utc_offset, -5.0);  // the longitude's nautical time zone
}

TEST(IfcImport, OpenHouseWallsAndOpeningsAreWhereTheModelHasThem) {
  const Result<IfcImport> r = import_ifc_file(model("IfcOpenHouse_IFC4.ifc"));
  ASSERT_TRUE(r.ok()) << r.error();
  const Plan& plan = r.value().plan;
  const Wall* south = find_wall(plan, "South wall");
  ASSERT_NE(south, nullptr);
  EXPECT_NEAR(south->thickness, 0.36, 1e-6);  // millimetres in the file, metres in the plan
  EXPECT_GT(south->height, 2.0);
  std::size_t doors = 0;
  for (const Opening& o : plan.openings) doors += o.type == OpeningType::door;
  EXPECT_EQ(doors, 1u);
}

Plan sample_plan() {
  Plan plan;
  plan.site.max_height = 9.0;
  plan.levels = {{.id = "ground", .elevation = 0.0, .height = 3.0},
                 {.id = "first", .elevation = 3.0, .height = 2.6}};
  auto wall = [&](const char* id, Point2 a, Point2 b, const char* level, double t) {
    Wall& w = plan.walls.emplace_back();
    w.id = id, w.from = a, w.to = b, w.level = level, w.thickness = t;
  };
  wall("south", {1, 1}, {11, 1}, "ground", 0.3);
  wall("east", {11, 1}, {11, 7}, "ground", 0.25);
  wall("north", {11, 7}, {1, 7}, "ground", 0.25);
  wall("west", {1, 7}, {1, 1}, "ground", 0.25);
  wall("mid", {6, 1}, {6, 7}, "ground", 0.1);
  wall("skew", {2, 2}, {5, 6}, "first", 0.2);
  plan.openings.push_back({.id = "entry",
                           .type = OpeningType::door,
                           .wall = "south",
                           .offset = 1.5,
                           .width = 0.9,
                           .height = 2.1,
                           .hinge = Hinge::right});
  plan.openings.push_back({.id = "arch",
                           .type = OpeningType::window,
                           .wall = "north",
                           .offset = 2,
                           .width = 1.2,
                           .height = 1.6,
                           .sill = 0.8,
                           .shape = {{0, 0}, {1, 0}, {1, 0.7}, {0.5, 1}, {0, 0.7}}});
  plan.openings.push_back({.id = "slot",
                           .type = OpeningType::window,
                           .wall = "skew",
                           .offset = 1,
                           .width = 2,
                           .height = 0.5,
                           .sill = 1.5});
  plan.slabs.push_back({.id = "floor1",
                        .level = "first",
                        .outline = {{1, 1}, {11, 1}, {11, 7}, {1, 7}},
                        .holes = {{{2, 5}, {4, 5}, {4, 6}, {2, 6}}},
                        .top = 0.0,
                        .thickness = 0.2});
  return plan;
}

void expect_near(Point2 a, Point2 b) {
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-6);
}

// Export then import: the same walls, openings, levels and slabs, to the micrometre.
void expect_round_trip(const Plan& original) {
  const Result<std::string> ifc = format_ifc(original, "round.ifc");
  ASSERT_TRUE(ifc.ok()) << ifc.error();
  const Result<IfcImport> back = import_ifc_text(ifc.value(), "round.ifc");
  ASSERT_TRUE(back.ok()) << back.error();
  // Nothing is approximated; only the spaces are left out (rooms come from the walls).
  for (const Diagnostic& d : back.value().warnings.items)
    if (d.message.find(" IFCSPACE ") == std::string::npos) ADD_FAILURE() << d.message;
  const Plan a = with_absolute_heights(original);
  const Plan b = with_absolute_heights(back.value().plan);
  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (const Wall& w : a.walls) {
    SCOPED_TRACE(w.id);
    const Wall* v = find_wall(b, w.id);
    ASSERT_NE(v, nullptr);
    expect_near(w.from, v->from);
    expect_near(w.to, v->to);
    EXPECT_NEAR(w.thickness, v->thickness, 1e-6);
    EXPECT_NEAR(w.height, v->height, 1e-6);
    EXPECT_NEAR(w.base, v->base, 1e-6);
  }
  ASSERT_EQ(a.openings.size(), b.openings.size());
  std::map<std::string, const Opening*> read;
  for (const Opening& p : b.openings) read[p.id] = &p;
  for (const Opening& o : a.openings) {
    SCOPED_TRACE(o.id);
    ASSERT_TRUE(read.contains(o.id));
    const Opening& p = *read[o.id];
    EXPECT_EQ(o.wall, p.wall);
    EXPECT_EQ(o.type, p.type);
    if (o.type == OpeningType::door) {
      EXPECT_EQ(o.hinge, p.hinge);
    }
    EXPECT_NEAR(o.offset, p.offset, 1e-6);
    EXPECT_NEAR(o.width, p.width, 1e-6);
    EXPECT_NEAR(o.sill, p.sill, 1e-6);
    EXPECT_NEAR(o.height, p.height, 1e-6);
    ASSERT_EQ(o.shape.size(), p.shape.size());
    for (std::size_t k = 0; k < o.shape.size(); ++k) expect_near(o.shape[k], p.shape[k]);
  }
  ASSERT_EQ(a.slabs.size(), b.slabs.size());
  for (std::size_t i = 0; i < a.slabs.size(); ++i) {
    EXPECT_NEAR(a.slabs[i].top, b.slabs[i].top, 1e-6);
    EXPECT_NEAR(a.slabs[i].thickness, b.slabs[i].thickness, 1e-6);
    ASSERT_EQ(a.slabs[i].outline.size(), b.slabs[i].outline.size());
    ASSERT_EQ(a.slabs[i].holes.size(), b.slabs[i].holes.size());
  }
  std::map<std::string, double> levels;
  for (const Level& l : b.levels) levels[l.id] = l.elevation;
  for (const Level& l : a.levels) EXPECT_NEAR(levels[l.id], l.elevation, 1e-6) << l.id;
}

TEST(IfcImport, ExportedPlanComesBackWithItsWallsOpeningsLevelsAndSlabs) {
  expect_round_trip(sample_plan());
}

TEST(IfcImport, EveryExamplePlanComesBackFromItsIfc) {
  for (const auto& path : test::example_plans()) {
    SCOPED_TRACE(path.filename().string());
    const Result<Plan> plan = read_plan_file(path);
    ASSERT_TRUE(plan.ok());
    expect_round_trip(plan.value());
  }
}

TEST(IfcImport, UnreadableModelsAreErrorsNamingTheFile) {
  const Result<IfcImport> text = import_ifc_text("{\"not\": \"ifc\"}", "x.ifc");
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error().code, Code::parse_error);
  const std::string head = "ISO-10303-21;HEADER;FILE_SCHEMA(('IFC5'));ENDSEC;DATA;";
  const Result<IfcImport> schema = import_ifc_text(head + "ENDSEC;END-ISO-10303-21;", "x.ifc");
  ASSERT_FALSE(schema.ok());
  EXPECT_EQ(schema.error().code, Code::unsupported);
  const std::string ifc4 = "ISO-10303-21;HEADER;FILE_SCHEMA(('IFC4'));ENDSEC;DATA;";
  const Result<IfcImport> empty = import_ifc_text(
      ifc4 + "#1=IFCPROJECT('0123456789012345678901',$,'p',$,$,$,$,$,$);ENDSEC;", "x.ifc");
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.error().code, Code::parse_error);
  EXPECT_NE(empty.error().message.find("x.ifc: no wall"), std::string::npos);
  const Result<IfcImport> missing = import_ifc_file("/nonexistent/model.ifc");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, Code::io_error);
}

TEST(IfcImport, AnElementItCannotReadIsAWarningNamingIt) {
  Plan plan = sample_plan();
  std::string ifc = format_ifc(plan, "x.ifc").value();
  // A curtain wall placed like the first wall.
  const std::size_t end = ifc.find("ENDSEC;", ifc.find("DATA;"));
  const std::size_t pos = ifc.find("=IFCLOCALPLACEMENT(", ifc.find("=IFCWALL(") - 400);
  const std::string placement = ifc.substr(ifc.rfind('#', pos), pos - ifc.rfind('#', pos));
  ifc.insert(end, "#99999=IFCCURTAINWALL('0aaaaaaaaaaaaaaaaaaaaa',$,'glass',$,$," + placement +
                      ",$,$,$);\n");
  const Result<IfcImport> r = import_ifc_text(ifc, "x.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  // The curtain wall (it has no body, nor members or plates), and the two spaces of the ground
  // floor (rooms come from the walls).
  ASSERT_EQ(r.value().warnings.items.size(), 3u);
  const Diagnostic& curtain = r.value().warnings.items.front();
  EXPECT_EQ(curtain.code, Code::import_skipped_element);
  EXPECT_TRUE(curtain.message.starts_with("#99999 IFCCURTAINWALL 'glass': not imported"))
      << curtain.message;
  EXPECT_EQ(r.value().tally.at("IFCCURTAINWALL").skipped, 1u);
  EXPECT_EQ(r.value().tally.at("IFCSPACE").skipped, 2u);
}

}  // namespace
}  // namespace roomcad
