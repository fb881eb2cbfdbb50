// SPDX-License-Identifier: GPL-3.0-or-later
// Every bundled example's exports as independent readers see them (tests/readers, installed by
// scripts/setup.sh; a missing reader fails these tests): the IFC in web-ifc, the GLB and glTF
// in the Khronos glTF validator, the DXF floor plan in ezdxf.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "import/ifc_import.h"
#include "io/floor_plan_dxf.h"
#include "io/plan_json.h"
#include "mesh/mesh_check.h"
#include "plan/arc_chords.h"
#include "readers_support.h"
#include "render/floor_plan.h"
#include "solid/analytic_volume.h"
#include "support/run_command.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

using test::run_reader;
using test::run_roomcad;
using test::TempDir;

Plan read_example(const std::filesystem::path& path) {
  const Result<Plan> plan = read_plan_file(path);
  EXPECT_TRUE(plan.ok()) << path;
  return plan.ok() ? plan.value() : Plan{};
}

std::size_t count_openings(const Plan& plan, OpeningType type) {
  return static_cast<std::size_t>(
      std::count_if(plan.openings.begin(), plan.openings.end(),
                    [type](const Opening& o) { return o.type == type; }));
}

// Exports the plan file `path` (holding `plan`) to IFC and checks it in web-ifc: its element
// counts are the plan's, and web-ifc, cutting each opening from its wall (float32 vertices),
// finds walls whose volumes add up to the plan's wall solid.
void expect_web_ifc_agrees(const std::filesystem::path& path, const Plan& plan,
                           const TempDir& dir) {
  const auto ifc = dir / (path.stem().string() + ".ifc");
  const auto built = run_roomcad({"build", path.string(), "-o", ifc.string()});
  ASSERT_EQ(built.status, 0) << built.err;
  const auto run = run_reader("ifc_check.cjs", ifc);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->status, 0) << run->report.dump() << run->err;
  const auto& counts = run->report["counts"];
  EXPECT_EQ(run->report["schema"], "IFC4");
  EXPECT_EQ(counts["IFCBUILDINGSTOREY"], std::max<std::size_t>(plan.levels.size(), 1));
  EXPECT_EQ(counts["IFCWALL"], plan.walls.size());
  EXPECT_EQ(counts["IFCOPENINGELEMENT"], plan.openings.size());
  EXPECT_EQ(counts["IFCRELVOIDSELEMENT"], plan.openings.size());
  EXPECT_EQ(counts["IFCRELFILLSELEMENT"], plan.openings.size());
  EXPECT_EQ(counts["IFCDOOR"], count_openings(plan, OpeningType::door));
  EXPECT_EQ(counts["IFCWINDOW"], count_openings(plan, OpeningType::window));
  EXPECT_EQ(counts["IFCSLAB"], plan.slabs.size());
  EXPECT_EQ(counts["IFCSPACE"], find_rooms(plan).size());
  double volume = 0.0;
  std::size_t walls = 0;
  for (const auto& product : run->report["products"]) {
    if (product["type"] != "IFCWALL") continue;
    volume += product["volume"].get<double>();
    ++walls;
  }
  EXPECT_EQ(walls, plan.walls.size());
  const double expected = analytic_wall_volume(plan);
  EXPECT_NEAR(volume, expected, 1e-5 * expected);
}

TEST(IndependentReaders, WebIfcOpensEveryExampleWithItsCountsAndWallVolume) {
  TempDir dir;
  for (const auto& path : test::example_plans()) {
    SCOPED_TRACE(path.filename().string());
    expect_web_ifc_agrees(path, read_example(path), dir);
  }
}

TEST(IndependentReaders, WebIfcCutsTheOpeningsOfAnArcWallAsTheBuildDoes) {
  // A room whose east wall bows out (version 2 arc_extent), a window across several of its
  // chords and a door ending exactly on a chord corner, where its void ends on the mitre.
  Plan plan;
  plan.site.cells = {12, 10}, plan.site.origin = {2, -1};
  plan.site.chord_tolerance = 0.05;  // five chords of about 1.25 m
  auto wall = [&](const char* id, Point2 a, Point2 b) -> Wall& {
    Wall& w = plan.walls.emplace_back();
    w.id = id, w.from = a, w.to = b;
    return w;
  };
  wall("s", {5, 1}, {11, 1});
  wall("bow", {11, 1}, {11, 7}).arc_extent = 60.0;
  wall("n", {11, 7}, {5, 7});
  wall("w", {5, 7}, {5, 1});
  const std::vector<Point2> chords = chord_polyline(plan.walls[1], chord_tolerance_of(plan.site));
  ASSERT_GT(chords.size(), 4u);
  const double corner = std::hypot(chords[1].x - chords[0].x, chords[1].y - chords[0].y);
  plan.openings.push_back({.id = "bay",
                           .type = OpeningType::window,
                           .wall = "bow",
                           .offset = 2.0,
                           .width = 1.6,
                           .height = 1.2,
                           .sill = 0.9});
  plan.openings.push_back({.id = "side",
                           .type = OpeningType::door,
                           .wall = "bow",
                           .offset = corner - 0.9,
                           .width = 0.9,
                           .height = 2.1});
  TempDir dir;
  const auto path = dir / "bow-room.json";
  ASSERT_TRUE(write_plan_file(plan, path).ok());
  expect_web_ifc_agrees(path, read_example(path), dir);
}

// The bundled IFC models (examples/ifc) import with the walls web-ifc meshes from the same
// files: the plan's walls from the IFC walls read (curtain walls aside: web-ifc meshes their
// members, not a solid wall) with their openings have web-ifc's volume of those walls
// (openings cut), within 2%. The plan's solid counts a corner two walls share once, web-ifc's
// sum of walls twice: IfcOpenHouse's walls overlap at its corners, so there each IFC wall's
// plan walls are measured alone, as web-ifc measures them; the others' walls are mitred or
// butt-jointed, where measured alone a plan wall's square end would count the mitre twice.
TEST(IndependentReaders, ImportedIfcWallsHaveTheVolumeWebIfcFindsInTheFile) {
  struct Model {
    const char* file;
    bool corners_in_two_walls;
  };
  for (const Model& m :
       {Model{"IfcOpenHouse_IFC4.ifc", true}, Model{"duplex.ifc", false},
        Model{"tested_sample_project.ifc", false}, Model{"bonsai_project0-openings.ifc", false},
        Model{"sikongsphere_complex.ifc", false}, Model{"bimwhale_TallBuilding.ifc", false}}) {
    SCOPED_TRACE(m.file);
    const auto path = test::source_dir() / "examples" / "ifc" / m.file;
    const Result<IfcImport> imported = import_ifc_file(path);
    ASSERT_TRUE(imported.ok()) << imported.error();
    const auto run = run_reader("ifc_check.cjs", path);
    ASSERT_TRUE(run);
    std::map<std::uint32_t, double> web_ifc;  // IFC entity -> volume
    for (const auto& product : run->report["products"])
      web_ifc[product["id"].get<std::uint32_t>()] = product["volume"].get<double>();
    const Plan& plan = imported.value().plan;
    Plan all;  // every wall compared, with its openings
    all.site = plan.site, all.levels = plan.levels;
    std::map<std::uint32_t, Plan> alone;  // IFC entity -> its plan walls and their openings
    std::set<std::uint32_t> compared;
    for (const Wall& w : plan.walls) {
      const std::uint32_t entity = imported.value().wall_sources.at(w.id);
      if (!web_ifc.contains(entity)) continue;  // a curtain wall
      compared.insert(entity);
      for (Plan* p : {&all, &alone[entity]}) {
        p->site = plan.site, p->levels = plan.levels;
        p->walls.push_back(w);
        for (const Opening& o : plan.openings)
          if (o.wall == w.id) p->openings.push_back(o);
      }
    }
    double ours = m.corners_in_two_walls ? 0.0 : analytic_wall_volume(all), theirs = 0.0;
    for (const std::uint32_t entity : compared) {
      theirs += web_ifc.at(entity);
      if (m.corners_in_two_walls) ours += analytic_wall_volume(alone.at(entity));
    }
    const auto& tally = imported.value().tally;
    const std::size_t curtain =
        tally.contains("IFCCURTAINWALL") ? tally.at("IFCCURTAINWALL").read : 0;
    EXPECT_EQ(compared.size() + curtain, imported.value().walls_read);
    EXPECT_NEAR(ours, theirs, 0.02 * theirs);
  }
}

TEST(IndependentReaders, GltfValidatorFindsNoErrorOrWarningInAnyExample) {
  TempDir dir;
  for (const auto& path : test::example_plans()) {
    for (const char* extension : {".glb", ".gltf"}) {
      const auto file = dir / (path.stem().string() + extension);
      SCOPED_TRACE(file.filename().string());
      const auto built = run_roomcad({"build", path.string(), "-o", file.string()});
      ASSERT_EQ(built.status, 0) << built.err;
      const auto run = run_reader("gltf_check.cjs", file);
      ASSERT_TRUE(run);
      EXPECT_EQ(run->status, 0) << run->report.dump(1);
      EXPECT_EQ(run->report["errors"], 0);
      EXPECT_EQ(run->report["warnings"], 0);
      EXPECT_GT(run->report["info"]["drawCallCount"].get<int>(), 0);
    }
  }
}

TEST(IndependentReaders, EzdxfReadsEveryExamplePlanWithItsLayersAndEntities) {
  TempDir dir;
  for (const auto& path : test::example_plans()) {
    SCOPED_TRACE(path.filename().string());
    const Plan plan = read_example(path);
    const auto dxf = dir / (path.stem().string() + ".dxf");
    const auto drawn = run_roomcad({"draw", path.string(), "--view", "plan", "-o", dxf.string()});
    ASSERT_EQ(drawn.status, 0) << drawn.err;
    const auto run = run_reader("dxf_check.py", dxf);
    ASSERT_TRUE(run);
    EXPECT_EQ(run->status, 0) << run->report.dump(1);
    EXPECT_EQ(run->report["version"], "AC1015");
    EXPECT_EQ(run->report["insunits"], 6);  // metres
    EXPECT_TRUE(run->report["audit_errors"].empty()) << run->report["audit_errors"].dump(1);
    for (const char* layer : kDxfLayers)
      EXPECT_NE(std::find(run->report["layers"].begin(), run->report["layers"].end(), layer),
                run->report["layers"].end())
          << layer;
    // The same drawing as `draw --view plan` makes by default (1:50, cut at 1 m).
    const FloorPlanDrawing d = draw_floor_plan(plan, {});
    std::map<std::string, std::map<std::string, std::size_t>> expected;
    auto add = [&expected](const char* layer, const char* type, std::size_t n) {
      if (n) expected[layer][type] += n;
    };
    add("WALLS_CUT", "LWPOLYLINE", d.cut_walls.size()),
        add("WALLS_CUT", "HATCH", d.cut_walls.size());
    add("WALLS_BELOW", "LWPOLYLINE", d.walls_below.size()),
        add("WALLS_ABOVE", "LWPOLYLINE", d.walls_above.size());
    add("WINDOWS", "LINE", d.windows.size());
    add("DOORS", "LINE", d.door_leaves.size()), add("DOORS", "ARC", d.door_swings.size());
    add("DIMENSIONS", "LINE", d.dimension_lines.size()),
        add("DIMENSIONS", "TEXT", d.dimension_texts.size());
    add("ROOMS", "LWPOLYLINE", d.rooms.size()), add("ROOMS", "TEXT", d.room_labels.size());
    EXPECT_EQ(run->report["entities"], nlohmann::json(expected));
    // True size in metres: the extent holds every wall end and lies within a few metres of them
    // (dimensions reach out), where paper millimetres at 1:50 would be 20 times larger.
    const auto& extent = run->report["extent"];
    for (const Wall& w : plan.walls) {
      for (const Point2 p : {w.from, w.to}) {
        EXPECT_LE(extent[0][0].get<double>(), p.x);
        EXPECT_GE(extent[1][0].get<double>(), p.x);
        EXPECT_LE(extent[0][1].get<double>(), p.y);
        EXPECT_GE(extent[1][1].get<double>(), p.y);
      }
    }
    const Site& s = plan.site;
    EXPECT_GE(extent[0][0].get<double>(), s.origin.x - 5.0);
    EXPECT_LE(extent[1][0].get<double>(), s.origin.x + s.cells[0] * s.cell_size + 5.0);
  }
}

// The checks above mean something only if the readers refuse bad files.
// The findings of bundled homes as BCF, read by @parametricos/bcf-js: one topic per finding,
// each selecting components that are IfcRoot GlobalIds of the plan's IFC export as web-ifc reads
// it, with a camera and a PNG snapshot from it; a later revision keeps the GUIDs of the findings it
// keeps.
TEST(IndependentReaders, BcfJsReadsTheFindingsAndTheirComponentsAreTheIfcExportsObjects) {
  TempDir dir;
  std::size_t components = 0;
  for (const char* home : {"3-BedroomApartment", "arif-home", "apartament-balanta"}) {
    SCOPED_TRACE(home);
    const auto plan =
        test::source_dir() / "examples" / "sweethome3d" / (std::string(home) + ".json");
    const auto bcf = dir / (std::string(home) + ".bcfzip");
    const auto ifc = dir / (std::string(home) + ".ifc");
    const auto validated =
        run_roomcad({"validate", plan.string(), "--format", "bcf", "-o", bcf.string()});
    EXPECT_EQ(validated.status, 1) << validated.err;
    ASSERT_EQ(run_roomcad({"build", plan.string(), "-o", ifc.string(), "--force"}).status, 0);
    const auto run = run_reader("bcf_check.cjs", std::vector{bcf, ifc});
    ASSERT_TRUE(run);
    EXPECT_EQ(run->status, 0) << run->report.dump() << run->err;
    EXPECT_EQ(run->report["version"], 2.1);
    const Report report = validate(read_example(plan));
    ASSERT_EQ(run->report["topics"].size(), report.items.size());
    std::set<std::string> global_ids;
    for (const auto& id : run->report["ifc_global_ids"]) global_ids.insert(id.get<std::string>());
    std::set<std::string> guids;
    for (const auto& topic : run->report["topics"]) {
      guids.insert(topic["guid"].get<std::string>());
      EXPECT_EQ(topic["status"], "Open");
      EXPECT_TRUE(topic["camera"].get<bool>()) << topic["title"];
      EXPECT_GT(topic["snapshot"].get<int>(), 1000) << topic["title"];  // a PNG from the camera
      for (const auto& c : topic["components"]) {
        EXPECT_TRUE(global_ids.contains(c.get<std::string>())) << topic["title"] << ' ' << c;
        ++components;
      }
    }
    EXPECT_EQ(guids.size(), report.items.size());  // one GUID per finding
  }
  EXPECT_GT(components, 20u);
}

TEST(IndependentReaders, BcfTopicsKeepTheirGuidsAcrossRevisionsAndFixedOnesClose) {
  TempDir dir;
  const auto old_plan = test::source_dir() / "examples" / "sweethome3d" / "3-BedroomApartment.json";
  const auto plan = dir / "plan.json";
  ASSERT_EQ(run_roomcad({"fmt", old_plan.string(), "-o", plan.string()}).status, 0);
  ASSERT_EQ(run_roomcad({"rm", plan.string(), "wall38", "--force", "--cascade"}).status, 0);
  const auto old_bcf = dir / "old.bcfzip";
  const auto bcf = dir / "new.bcfzip";
  ASSERT_EQ(run_roomcad({"validate", old_plan.string(), "--format", "bcf", "-o", old_bcf.string()})
                .status,
            1);
  ASSERT_EQ(run_roomcad({"validate", plan.string(), "--format", "bcf", "-o", bcf.string(),
                         "--baseline", old_plan.string()})
                .status,
            1);
  const auto before = run_reader("bcf_check.cjs", old_bcf);
  const auto after = run_reader("bcf_check.cjs", bcf);
  ASSERT_TRUE(before && after);
  std::map<std::string, std::string> status_of;  // GUID -> status in the later revision
  for (const auto& t : after->report["topics"]) status_of[t["guid"]] = t["status"];
  std::size_t kept = 0, closed = 0;
  for (const auto& t : before->report["topics"]) {
    const auto found = status_of.find(t["guid"]);
    ASSERT_NE(found, status_of.end()) << t["title"];  // every finding: open or closed
    kept += found->second == "Open";
    closed += found->second == "Closed";
  }
  EXPECT_GT(kept, 0u);
  EXPECT_GT(closed, 0u);  // the overlaps of wall38, gone with it
}

TEST(IndependentReaders, RejectBrokenFiles) {
  TempDir dir;
  const auto examples = test::example_plans();
  ASSERT_FALSE(examples.empty());
  const auto glb = dir / "cut.glb";
  ASSERT_EQ(run_roomcad({"build", examples.front().string(), "-o", glb.string()}).status, 0);
  const std::string bytes = test::read_bytes(glb);
  ASSERT_TRUE(test::write_bytes(glb, bytes.substr(0, bytes.size() / 2)));
  const auto gltf = run_reader("gltf_check.cjs", glb);
  ASSERT_TRUE(gltf);
  EXPECT_EQ(gltf->status, 1);
  EXPECT_GT(gltf->report["errors"].get<int>(), 0);
  const auto dxf = dir / "bad.dxf";
  ASSERT_TRUE(
      test::write_bytes(dxf, "  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n 10\nnot a number\n"));
  const auto ezdxf = run_reader("dxf_check.py", dxf);
  ASSERT_TRUE(ezdxf);
  EXPECT_EQ(ezdxf->status, 1);
}

}  // namespace
}  // namespace roomcad
