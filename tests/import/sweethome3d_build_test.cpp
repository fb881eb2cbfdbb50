// SPDX-License-Identifier: GPL-3.0-or-later
// Building the imported Sweet Home 3D homes: every home gives a closed, valid wall solid whose
// volume matches the volume computed from the plan alone, and the same solid, face kind by
// face kind, without the general path's grid of planes of rectangles (BuildOptions::grid_planes).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "import/sh3d_test_data.h"
#include "mesh/mesh_check.h"
#include "solid/analytic_volume.h"
#include "solid/build_model.h"
#include "support/solid_tolerance.h"

namespace roomcad {
namespace {

using namespace sh3d_test;

// Every bundled home: the example homes and the community homes.
std::vector<fs::path> homes_to_build() {
  std::vector<fs::path> homes = all_homes();
  for (const auto& e : fs::directory_iterator(kData / "community-homes")) homes.push_back(e.path());
  return homes;
}

// The solid of walls and slabs.
BuildOptions walls_and_slabs() {
  BuildOptions options;
  options.parts.floor = false;
  options.parts.fixtures = false;
  return options;
}

TEST(Sh3dBuild, HomesBuildAClosedSolidOfTheAnalyticVolume) {
  // Every home as imported, version 2 geometry and all: levels, floors, sloped tops, arcs and
  // cut-out shapes. Their validation errors are the homes' own (walls drawn over each other),
  // so they are built as `build --force` does.
  for (const fs::path& home : homes_to_build()) {
    SCOPED_TRACE(home.filename().string());
    const Plan plan = import_or_fail(home).plan;
    Model model;
    ASSERT_NO_THROW(model = build_model(plan, walls_and_slabs()));
    const SolidCheck check = check_solid(model.walls);
    EXPECT_TRUE(check.is_closed());
    EXPECT_TRUE(check.is_valid()) << "border edges " << check.border_edges << ", non-manifold "
                                  << check.non_manifold_vertices << ", self-intersections "
                                  << check.self_intersections;
    const double expected = analytic_wall_volume(plan);
    EXPECT_GT(expected, 1.0);
    EXPECT_NEAR(check.volume, expected, 1e-9 * expected) << "cubic metres";
  }
}

TEST(Sh3dBuild, GridPlanesBuildTheSolidOfTheGeneralBoolean) {
  // The general path's planes of rectangles on their grid (detail/grid_faces.h) against every
  // plane through the general 2D boolean: one solid, face kind by face kind.
  for (const fs::path& home : homes_to_build()) {
    SCOPED_TRACE(home.filename().string());
    const Plan plan = import_or_fail(home).plan;
    BuildOptions options = walls_and_slabs();
    const Model grid = build_model(plan, options);
    options.grid_planes = false;
    const Model boolean = build_model(plan, options);
    const SolidCheck a = check_solid(grid.walls), b = check_solid(boolean.walls);
    EXPECT_TRUE(a.is_valid());
    EXPECT_TRUE(b.is_valid());
    EXPECT_EQ(a.genus, b.genus);
    EXPECT_NEAR(a.volume, b.volume, 1e-9 * b.volume) << "cubic metres";
    const auto areas = test::area_by_kind(grid.walls),
               reference = test::area_by_kind(boolean.walls);
    ASSERT_EQ(areas.size(), reference.size());
    for (const auto& [kind, area] : reference) {
      ASSERT_TRUE(areas.count(kind)) << to_string(kind);
      EXPECT_NEAR(areas.at(kind), area, 1e-9 * area) << to_string(kind) << ", square metres";
    }
  }
}

}  // namespace
}  // namespace roomcad
