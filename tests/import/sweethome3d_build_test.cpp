// SPDX-License-Identifier: GPL-3.0-or-later
// Building the imported Sweet Home 3D homes: every home gives a closed, valid wall solid whose
// volume matches the volume computed from the plan alone.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "import/sh3d_test_data.h"
#include "modeling/build_model.h"
#include "modeling/mesh_check.h"

namespace roomcad {
namespace {

using namespace sh3d_test;

TEST(Sh3dBuild, HomesBuildAClosedSolidOfTheAnalyticVolume) {
  // Every home as imported, version 2 geometry and all: levels, floors, sloped tops, arcs and
  // cut-out shapes. Their validation errors are the homes' own (walls drawn over each other),
  // so they are built as `build --force` does.
  std::vector<fs::path> homes = all_homes();
  for (const auto& e : fs::directory_iterator(kData / "community-homes")) homes.push_back(e.path());
  for (const fs::path& home : homes) {
    SCOPED_TRACE(home.filename().string());
    const Plan plan = import_or_fail(home).plan;
    BuildOptions options;
    options.parts.floor = false;
    options.parts.fixtures = false;
    Model model;
    ASSERT_NO_THROW(model = build_model(plan, options));
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

}  // namespace
}  // namespace roomcad
