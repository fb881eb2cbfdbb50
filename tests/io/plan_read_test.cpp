// SPDX-License-Identifier: GPL-3.0-or-later
// Reading plans: every field, every default, units.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "plan_test_support.h"
#include "support/plan_reading.h"

namespace roomcad {
namespace {

using test::read_ok;

// The site of the spec's example, which is also every field's default.
void expect_spec_site(const Site& site) {
  EXPECT_EQ(site.origin, (Point2{0, 0}));
  EXPECT_EQ(site.cells, (std::array<std::int64_t, 2>{12, 8}));
  EXPECT_EQ(site.cell_size, 1.0);
  EXPECT_EQ(site.max_height, 6.0);
  EXPECT_EQ(site.tolerance, 1e-6);
  EXPECT_EQ(site.floor_color, (Color{0xc8, 0xc8, 0xc8}));
}

TEST(PlanRead, SpecExampleGivesEveryField) {
  const Plan p = read_ok(test::kSpecExample);
  expect_spec_site(p.site);

  ASSERT_EQ(p.walls.size(), 1u);
  const Wall& w = p.walls[0];
  EXPECT_EQ(w.id, "south");
  EXPECT_EQ(w.from, (Point2{1, 1}));
  EXPECT_EQ(w.to, (Point2{11, 1}));
  EXPECT_EQ(w.thickness, 0.25);
  EXPECT_EQ(w.height, 2.8);
  EXPECT_EQ(w.base, 0.0);
  EXPECT_EQ(w.color, (Color{0xe8, 0xe2, 0xd0}));

  ASSERT_EQ(p.openings.size(), 2u);
  const Opening& door = p.openings[0];
  EXPECT_EQ(door.id, "entry");
  EXPECT_EQ(door.type, OpeningType::door);
  EXPECT_EQ(door.wall, "south");
  EXPECT_EQ(door.offset, 1.5);
  EXPECT_EQ(door.width, 0.9);
  EXPECT_EQ(door.height, 2.1);
  EXPECT_EQ(door.sill, 0.0);
  EXPECT_EQ(door.hinge, Hinge::left);
  EXPECT_EQ(door.swing, Swing::in);
  const Opening& window = p.openings[1];
  EXPECT_EQ(window.id, "win1");
  EXPECT_EQ(window.type, OpeningType::window);
  EXPECT_EQ(window.offset, 5.0);
  EXPECT_EQ(window.width, 1.4);
  EXPECT_EQ(window.height, 1.3);
  EXPECT_EQ(window.sill, 0.9);

  ASSERT_EQ(p.lights.size(), 1u);
  EXPECT_EQ(p.lights[0].id, "sun");
  EXPECT_EQ(p.lights[0].type, LightType::directional);
  EXPECT_EQ(p.lights[0].direction, (Vec3{-0.4, 0.5, -1.0}));
  EXPECT_EQ(p.lights[0].intensity, 1.0);
  EXPECT_EQ(p.lights[0].ambient, 0.25);

  ASSERT_EQ(p.cameras.size(), 2u);
  const Camera& view = p.cameras[0];
  EXPECT_EQ(view.id, "view");
  EXPECT_EQ(view.projection, Projection::perspective);
  EXPECT_EQ(view.eye, (Vec3{16, -9, 10}));
  EXPECT_EQ(view.target, (Vec3{6, 4, 1}));
  EXPECT_EQ(view.up, (Vec3{0, 0, 1}));
  EXPECT_EQ(view.fov_deg, 50.0);
  EXPECT_EQ(view.view_height, 10.0);  // default
  const Camera& top = p.cameras[1];
  EXPECT_EQ(top.projection, Projection::orthographic);
  EXPECT_EQ(top.up, (Vec3{0, 1, 0}));
  EXPECT_EQ(top.fov_deg, 50.0);  // default
  EXPECT_EQ(top.view_height, 10.0);
  EXPECT_TRUE(p.extra.empty());
}

TEST(PlanRead, EmptyObjectIsTheDefaultPlan) {
  EXPECT_EQ(read_ok("{}"), Plan{});
  // format, version and units may be left out; the sections may be empty.
  EXPECT_EQ(read_ok(R"({"site": {}, "walls": [], "openings": [], "lights": [], "cameras": []})"),
            Plan{});
}

TEST(PlanRead, SiteDefaults) {
  const Plan p = read_ok(R"({"site": {}})");
  expect_spec_site(p.site);
}

TEST(PlanRead, WallDefaults) {
  const Plan p = read_ok(R"({"walls": [{"id": "a", "from": [0, 0], "to": [3, 4]}]})");
  ASSERT_EQ(p.walls.size(), 1u);
  EXPECT_EQ(p.walls[0].thickness, 0.25);
  EXPECT_EQ(p.walls[0].height, 2.8);
  EXPECT_EQ(p.walls[0].base, 0.0);
  EXPECT_EQ(p.walls[0].color, (Color{0xe8, 0xe2, 0xd0}));
}

TEST(PlanRead, OpeningDefaultsDependOnType) {
  const Plan p = read_ok(R"({"openings": [
    {"id": "d", "wall": "a", "offset": 1},
    {"id": "e", "type": "door", "wall": "a", "offset": 1},
    {"id": "w", "type": "window", "wall": "a", "offset": 1},
    {"id": "v", "width": 2, "sill": 0.5, "type": "window", "wall": "a", "offset": 1}]})");
  ASSERT_EQ(p.openings.size(), 4u);
  for (int i : {0, 1}) {
    const Opening& d = p.openings[i];
    EXPECT_EQ(d.type, OpeningType::door);
    EXPECT_EQ(d.width, 0.9);
    EXPECT_EQ(d.height, 2.1);
    EXPECT_EQ(d.sill, 0.0);
    EXPECT_EQ(d.hinge, Hinge::left);
    EXPECT_EQ(d.swing, Swing::in);
  }
  const Opening& w = p.openings[2];
  EXPECT_EQ(w.width, 1.4);
  EXPECT_EQ(w.height, 1.3);
  EXPECT_EQ(w.sill, 0.9);
  // Given fields win even when `type` comes after them.
  const Opening& v = p.openings[3];
  EXPECT_EQ(v.width, 2.0);
  EXPECT_EQ(v.height, 1.3);
  EXPECT_EQ(v.sill, 0.5);
}

TEST(PlanRead, EveryEnumValue) {
  const Plan p = read_ok(R"({"openings": [
    {"id": "a", "wall": "w", "offset": 0, "hinge": "right", "swing": "out"},
    {"id": "b", "wall": "w", "offset": 0, "hinge": "left", "swing": "in"}],
    "lights": [{"id": "l", "type": "directional"}],
    "cameras": [{"id": "c", "projection": "orthographic", "eye": [0, 0, 1], "target": [0, 0, 0]},
                {"id": "d", "projection": "perspective", "eye": [0, 0, 1], "target": [0, 0, 0]}]})");
  EXPECT_EQ(p.openings[0].hinge, Hinge::right);
  EXPECT_EQ(p.openings[0].swing, Swing::out);
  EXPECT_EQ(p.openings[1].hinge, Hinge::left);
  EXPECT_EQ(p.openings[1].swing, Swing::in);
  EXPECT_EQ(p.lights[0].type, LightType::directional);
  EXPECT_EQ(p.cameras[0].projection, Projection::orthographic);
  EXPECT_EQ(p.cameras[1].projection, Projection::perspective);
}

TEST(PlanRead, LightAndCameraDefaults) {
  const Plan p = read_ok(R"({"lights": [{"id": "l"}],
    "cameras": [{"id": "c", "eye": [1, 2, 3], "target": [4, 5, 6]}]})");
  EXPECT_EQ(p.lights[0].type, LightType::directional);
  EXPECT_EQ(p.lights[0].direction, (Vec3{-0.4, 0.5, -1.0}));
  EXPECT_EQ(p.lights[0].intensity, 1.0);
  EXPECT_EQ(p.lights[0].ambient, 0.25);
  const Camera& c = p.cameras[0];
  EXPECT_EQ(c.projection, Projection::perspective);
  EXPECT_EQ(c.eye, (Vec3{1, 2, 3}));
  EXPECT_EQ(c.target, (Vec3{4, 5, 6}));
  EXPECT_EQ(c.up, (Vec3{0, 0, 1}));
  EXPECT_EQ(c.fov_deg, 50.0);
  EXPECT_EQ(c.view_height, 10.0);
}

TEST(PlanRead, ColoursInEitherCase) {
  const Plan p = read_ok(R"({"site": {"floor_color": "#A0b1C2"}})");
  EXPECT_EQ(p.site.floor_color, (Color{0xa0, 0xb1, 0xc2}));
}

TEST(PlanRead, NumbersAreReadToTheNearestDouble) {
  const Plan p =
      read_ok(R"({"walls": [{"id": "a", "from": [0.1, -0.3], "to": [1e-3, 12345678901234567890],
    "thickness": 0.30000000000000004, "height": 2.7999999999999998, "base": -0}]})");
  const Wall& w = p.walls[0];
  EXPECT_EQ(w.from, (Point2{0.1, -0.3}));
  EXPECT_EQ(w.to.x, 0.001);
  EXPECT_EQ(w.to.y, 12345678901234567890.0);
  EXPECT_EQ(w.thickness, 0.1 + 0.2);
  EXPECT_EQ(w.height, 2.8);
  EXPECT_EQ(w.base, 0.0);
  EXPECT_TRUE(std::signbit(w.base)) << "-0 keeps its sign";
}

TEST(PlanRead, CentimetresAndMillimetresBecomeMetres) {
  const std::string body = R"("site": {"origin": [100, -250], "cells": [12, 8], "cell_size": 50,
      "max_height": 600, "tolerance": 0.0001},
    "walls": [{"id": "a", "from": [100, 100], "to": [1100, 100], "thickness": 25, "height": 280,
      "base": 10}],
    "openings": [{"id": "o", "type": "window", "wall": "a", "offset": 150, "width": 90,
      "height": 120, "sill": 90}],
    "lights": [{"id": "l", "direction": [-0.4, 0.5, -1], "intensity": 0.8, "ambient": 0.3}],
    "cameras": [{"id": "c", "eye": [1600, -900, 1000], "target": [600, 400, 100], "up": [0, 0, 1],
      "fov_deg": 45, "view_height": 1000}]})";
  for (const auto& [units, scale] : {std::pair{"cm", 100.0}, std::pair{"mm", 1000.0}}) {
    SCOPED_TRACE(units);
    const Plan p = read_ok(std::string(R"({"units": ")") + units + "\", " + body);
    EXPECT_EQ(p.site.origin, (Point2{100 / scale, -250 / scale}));
    EXPECT_EQ(p.site.cells, (std::array<std::int64_t, 2>{12, 8}));  // a count, not a length
    EXPECT_EQ(p.site.cell_size, 50 / scale);
    EXPECT_EQ(p.site.max_height, 600 / scale);
    EXPECT_EQ(p.site.tolerance, 0.0001 / scale);
    const Wall& w = p.walls[0];
    EXPECT_EQ(w.from, (Point2{100 / scale, 100 / scale}));
    EXPECT_EQ(w.to, (Point2{1100 / scale, 100 / scale}));
    EXPECT_EQ(w.thickness, 25 / scale);
    EXPECT_EQ(w.height, 280 / scale);
    EXPECT_EQ(w.base, 10 / scale);
    const Opening& o = p.openings[0];
    EXPECT_EQ(o.offset, 150 / scale);
    EXPECT_EQ(o.width, 90 / scale);
    EXPECT_EQ(o.height, 120 / scale);
    EXPECT_EQ(o.sill, 90 / scale);
    // Directions, intensities, angles and `up` are not lengths.
    EXPECT_EQ(p.lights[0].direction, (Vec3{-0.4, 0.5, -1}));
    EXPECT_EQ(p.lights[0].intensity, 0.8);
    EXPECT_EQ(p.lights[0].ambient, 0.3);
    const Camera& c = p.cameras[0];
    EXPECT_EQ(c.eye, (Vec3{1600 / scale, -900 / scale, 1000 / scale}));
    EXPECT_EQ(c.target, (Vec3{600 / scale, 400 / scale, 100 / scale}));
    EXPECT_EQ(c.up, (Vec3{0, 0, 1}));
    EXPECT_EQ(c.fov_deg, 45.0);
    EXPECT_EQ(c.view_height, 1000 / scale);
  }
  // In cm, 280 cm is exactly the metre value written as 2.8.
  EXPECT_EQ(
      read_ok(
          R"({"units": "cm", "walls": [{"id": "a", "from": [0, 0], "to": [1, 0], "height": 280}]})")
          .walls[0]
          .height,
      2.8);
}

TEST(PlanRead, DefaultsAreInMetresWhateverTheUnits) {
  const Plan p = read_ok(R"({"units": "mm", "walls": [{"id": "a", "from": [0, 0], "to": [1000, 0]}],
    "openings": [{"id": "w", "type": "window", "wall": "a", "offset": 100}]})");
  EXPECT_EQ(p.walls[0].thickness, 0.25);
  EXPECT_EQ(p.walls[0].height, 2.8);
  EXPECT_EQ(p.openings[0].sill, 0.9);
  EXPECT_EQ(p.site.tolerance, 1e-6);
}

TEST(PlanRead, UnitsMayComeAfterTheLengths) {
  const Plan p =
      read_ok(R"({"walls": [{"id": "a", "from": [0, 0], "to": [500, 0]}], "units": "cm"})");
  EXPECT_EQ(p.walls[0].to.x, 5.0);
}

TEST(PlanRead, ReadsAFileAndNamesIt) {
  const Result<Plan> missing = read_plan_file("/nonexistent/roomcad/plan.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.code(), Code::io_error);
  EXPECT_NE(missing.message().find("/nonexistent/roomcad/plan.json"), std::string::npos);
  EXPECT_NE(missing.message().find("No such file"), std::string::npos);

  const Result<Plan> directory = read_plan_file("/tmp");
  ASSERT_FALSE(directory.ok());
  EXPECT_EQ(directory.code(), Code::io_error);
  EXPECT_NE(directory.message().find("directory"), std::string::npos);
}

}  // namespace
}  // namespace roomcad
