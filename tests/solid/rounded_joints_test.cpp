// SPDX-License-Identifier: GPL-3.0-or-later
// Joints where two nearly collinear walls end side by side and a third wall meets them: the
// exact union has slivers narrower than a double's step, which rounding must not turn into a
// crash or a broken mesh. Reduced from the Sweet Home 3D homes 4-BedroomHouse and
// 3-BedroomHouseWithMezzanine; and ceilings whose corners lie within an ulp of a wall, which
// rounding makes touch it (3-BedroomApartment and 4-BedroomHouse imported with --ceilings).
#include <string>

#include <gtest/gtest.h>

#include "solid/detail/assembly/face_soup.h"
#include "support/model_support.h"

namespace roomcad {
namespace {

using test::add_wall;
using test::empty_plan;
using test::expect_valid_walls;

Wall& add_thick_wall(Plan& plan, const std::string& id, Point2 from, Point2 to, double thickness) {
  Wall& w = add_wall(plan, id, from, to);
  w.thickness = thickness;
  return w;
}

// 4-BedroomHouse: wall28 and wall29 meet nearly collinear (1e-7 m off over 3.6 m) where
// wall27 ends on them; their rounded end faces leave a sliver whose corners round together.
TEST(RoundedJoints, TeeAtTheJointOfNearlyCollinearWallsBuildsAClosedSolid) {
  Plan plan = empty_plan();
  add_thick_wall(plan, "wall27", {2.8328528, -4.660859}, {-0.055, -4.661003}, 0.16);
  add_thick_wall(plan, "wall28", {-0.054999900000000004, -8.265}, {-0.055, -4.661003}, 0.26);
  add_thick_wall(plan, "wall29", {-0.055, -4.661003}, {-0.055, -2.300593}, 0.26);
  expect_valid_walls(plan, BooleanPath::automatic, 0);
  expect_valid_walls(plan, BooleanPath::nef, 0);
}

// 3-BedroomHouseWithMezzanine: the same joint, where rounding also leaves a groove 1 ulp wide
// at the node (a zero-width fin once rounded): it builds closed and 2-manifold on both paths.
TEST(RoundedJoints, TeeAtAJointWithAGrooveOneUlpWideBuildsAClosedSolid) {
  Plan plan = empty_plan();
  add_thick_wall(plan, "wall30", {-0.013000030000000001, -4.0055908}, {6.005, -4.0300632}, 0.16);
  add_thick_wall(plan, "wall32", {-0.013000030000000001, -4.0055908}, {-0.013000183, 0.02025055},
                 0.26);
  add_thick_wall(plan, "wall46", {-0.012999873, -9.818}, {-0.013000030000000001, -4.0055908}, 0.26);
  expect_valid_walls(plan, BooleanPath::automatic, 0);
  expect_valid_walls(plan, BooleanPath::nef, 0);
}

// 3-BedroomHouseWithMezzanine upstairs: wall2 and wall62 run on from each other 7.5e-8 rad
// apart where wall24 also ends; their square ends would leave a wedge about 1e-11 m wide
// (a needle face in doubles). Mitred to each other instead, the solid is closed and clean.
TEST(RoundedJoints, HairlineWedgeBetweenSquareEndsIsMitredShut) {
  Plan plan = empty_plan();
  add_thick_wall(plan, "wall2", {-0.013000000000000001, 0.020250525000000002},
                 {-0.01300018, -4.080249}, 0.26);
  add_thick_wall(plan, "wall24", {-0.01300018, -4.080249}, {3.287, -4.080249}, 0.26);
  add_thick_wall(plan, "wall62", {-0.01300018, -4.080249}, {-0.013000000000000001, -9.818316},
                 0.26);
  for (Wall& w : plan.walls) w.base = 2.5, w.height = 2.619999885559082;
  plan.walls[2].height = 1.119999885559082;  // wall62 is lower
  expect_valid_walls(plan, BooleanPath::automatic, 0);
  expect_valid_walls(plan, BooleanPath::nef, 0);
}

detail::SoupFace triangle(OpenMesh::Vec3d a, OpenMesh::Vec3d b, OpenMesh::Vec3d c, int object) {
  return {{a, b, c}, FaceKind::wall_face, object, {}, {}, {}};
}

std::string assembly_error(const detail::FaceSoup& soup) {
  try {
    (void)detail::assemble_mesh({&soup, 1}, {"first", "second"});
  } catch (const PreconditionError& e) {
    return e.what();
  }
  return "";
}

TEST(RoundedJoints, FaceOnAnEdgeThatHasOneNamesBothWalls) {
  const OpenMesh::Vec3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, -1, 0);
  const std::string what = assembly_error({triangle(a, b, c, 0), triangle(a, b, d, 1)});
  EXPECT_NE(what.find("of 'second'"), std::string::npos) << what;
  EXPECT_NE(what.find("'first' is already on that side"), std::string::npos) << what;
}

TEST(RoundedJoints, FaceRepeatingACornerIsAnError) {
  const OpenMesh::Vec3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const detail::FaceSoup soup{{{a, b, a, c}, FaceKind::wall_end, 1, {}, {}, {}}};
  EXPECT_NE(assembly_error(soup).find("repeats a corner"), std::string::npos);
}

TEST(RoundedJoints, FaceOfTwoCornersIsAnError) {
  const detail::FaceSoup soup{
      {{OpenMesh::Vec3d(0, 0, 0), OpenMesh::Vec3d(1, 0, 0)}, FaceKind::wall_top, 0, {}, {}, {}}};
  EXPECT_NE(assembly_error(soup).find("2 corners, fewer than 3"), std::string::npos);
}

Slab& add_ceiling(Plan& plan, Polygon outline) {
  Slab& s = plan.slabs.emplace_back();
  s.id = "ceiling", s.outline = std::move(outline);
  s.top = 2.619999885559082, s.thickness = 0.11999988555908203;  // from 2.5 up, as imported
  return s;
}

// 3-BedroomApartment imported with --ceilings: a ceiling's corner (7.5855690000000005,
// -3.6870822) lies 9e-17 m off wall19's top edge, which rounds onto it. The solid as written
// touches itself there, at a point (a copy of it per side), and does not cross itself.
TEST(RoundedJoints, CeilingCornerThatRoundsOntoAWallsEdgeTouchesIt) {
  Plan plan = empty_plan();
  add_thick_wall(plan, "wall19", {7.5696497, -3.7245822}, {8.769, -3.7245822}, 0.075);
  add_ceiling(plan, {{5.506124, -0.27787487},
                     {5.506124, -3.1054820000000003},
                     {5.506124, -3.682957},
                     {7.510569, -3.6870822},
                     {7.510569, -3.109607},
                     {7.5855690000000005, -3.109607},
                     {7.5855690000000005, -3.6870822},
                     {7.741136, -3.682957},
                     {7.741136, -3.7207068},
                     {8.6683356, -3.7207068},
                     {8.6683356, -3.682957},
                     {8.733068, -3.682957},
                     {8.733068, -2.5204575},
                     {8.733068, -0.27787487}});
  const SolidCheck c = expect_valid_walls(plan, BooleanPath::automatic, 0);
  EXPECT_GT(c.touching_pairs, 0u);
}

// 4-BedroomHouse imported with --ceilings: the ceiling's corner, laid a quarter of wall20's
// thickness into it, pokes 2e-16 m into wall43 along 1.5e-12 m. Rounded, the sliver between
// them collapses to an edge that four faces share (wall43's top and side, the ceiling's
// underside and edge): each pair across its own material takes a copy of the edge.
TEST(RoundedJoints, CeilingCornerInAWallByLessThanAnUlpBuildsAClosedSolid) {
  Plan plan = empty_plan();
  add_thick_wall(plan, "wall20", {9.3261584, -1.9480670000000002}, {9.3261584, -1.7265110000000001},
                 0.075);
  add_thick_wall(plan, "wall43", {9.648019000000001, -1.9480670000000002},
                 {9.3261584, -1.9480670000000002}, 0.075);
  add_ceiling(plan, {{8.108, -1.7640110000000002},
                     {8.108, -3.0930927},
                     {8.164956, -3.0930927},
                     {8.164956, -3.1308426},
                     {9.092156000000001, -3.1308426},
                     {9.092156000000001, -3.0930927},
                     {9.6109705, -3.0930927},
                     {9.6109705, -1.9856142},
                     {9.288658400000001, -1.985567},
                     {9.288658400000001, -1.7640110000000002}});
  const SolidCheck c = expect_valid_walls(plan, BooleanPath::automatic, 0);
  EXPECT_GT(c.touching_pairs, 0u);
}

// A closed fan of four triangles round v, then one more face at v: OpenMesh has no gap there.
TEST(RoundedJoints, FaceAtACornerClosedAllRoundIsAnError) {
  const OpenMesh::Vec3d v(0, 0, 0), a(1, 0, 0), b(0, 1, 0), c(-1, 0, 0), d(0, -1, 0);
  const OpenMesh::Vec3d e(0, 0, 1), f(0, 0, -1);
  const detail::FaceSoup soup{triangle(v, a, b, 0), triangle(v, b, c, 0), triangle(v, c, d, 0),
                              triangle(v, d, a, 0), triangle(v, e, f, 1)};
  EXPECT_NE(assembly_error(soup).find("complex vertex"), std::string::npos);
}

std::string closedness_error(const detail::FaceSoup& soup) {
  const std::vector<std::string> objects{"first", "second"};
  try {
    detail::require_closed(detail::assemble_mesh({&soup, 1}, objects), objects);
  } catch (const PreconditionError& e) {
    EXPECT_EQ(e.code(), Code::not_buildable);
    return e.what();
  }
  return "";
}

// A tetrahedron is closed; without one face, the three edges round the gap name the objects
// of the faces beside them.
TEST(RoundedJoints, ASolidWithAFaceMissingIsRefusedNamingTheFacesBesideTheGap) {
  const OpenMesh::Vec3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const detail::FaceSoup closed{triangle(o, y, x, 0), triangle(o, x, z, 0), triangle(o, z, y, 1),
                                triangle(x, y, z, 1)};
  EXPECT_EQ(closedness_error(closed), "");
  const std::string what = closedness_error({closed.begin(), closed.end() - 1});
  EXPECT_NE(what.find("not closed beside the faces of 'first', 'second': 3 edges"),
            std::string::npos)
      << what;
}

}  // namespace
}  // namespace roomcad
