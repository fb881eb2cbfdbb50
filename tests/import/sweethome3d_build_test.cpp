// SPDX-License-Identifier: GPL-3.0-or-later
// Building the imported Sweet Home 3D homes: every home gives a closed, valid wall solid whose
// volume matches the volume computed from the plan alone.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "import/sh3d_test_data.h"
#include "modeling/build_model.h"
#include "modeling/mesh_check.h"

namespace roomcad {
namespace {

using namespace sh3d_test;

// The homes whose walls build today: the one-storey homes of straight, flat-topped walls.
// 3-BedroomHouseWithMezzanine stops in build_model with a clear error ("a wall_face face of
// 'wall30' ... would make the mesh non-manifold: a corner is closed all round"), at a T that
// meets the joint of two nearly collinear walls: rounding the exact union leaves a groove one
// double step wide there (reduced in tests/modeling/rounded_joints_test.cpp). The homes with
// levels, sloped or curved walls (1-BedroomApartment, 2-BedroomHouseWithBasement,
// 3-BedroomHouseWithAttic, 4-BedroomHouse, Sample) are imported as version 2 plans, which the
// build reads from the general path on (issue 15): they join this list with it.
const char* const kBuildingHomes[] = {
    "eteks-example-homes/2-BedroomApartment", "eteks-example-homes/3-BedroomApartment",
    "eteks-example-homes/ApartmentWithBowWindow", "eteks-example-homes/Studio"};

TEST(Sh3dBuild, HomesBuildAClosedSolidOfTheAnalyticVolume) {
  for (const char* name : kBuildingHomes) {
    const fs::path home = kData / (std::string(name) + ".Home.xml");
    SCOPED_TRACE(name);
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
