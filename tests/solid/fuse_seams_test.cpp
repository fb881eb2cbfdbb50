// SPDX-License-Identifier: GPL-3.0-or-later
// The fast path fuses faces across the seams where two collinear walls meet a stem at a hub.
#include <gtest/gtest.h>

#include "solid/detail/fast_path/fuse_seams.h"
#include "support/model_support.h"
#include "testing/grid_plan.h"

namespace roomcad {
namespace {

// Walls a and b collinear along y = 0, meeting stem c at (4, 0): a three-arm hub.
Plan collinear_tee(Color a_colour, Color b_colour) {
  Plan plan = test::empty_plan();
  test::add_wall(plan, "a", {0, 0}, {4, 0}).color = a_colour;
  test::add_wall(plan, "b", {4, 0}, {8, 0}).color = b_colour;
  test::add_wall(plan, "c", {4, 0}, {4, 3});
  test::add_opening(plan, "win", OpeningType::window, "b", 1.0, 1.5, 0.9, 1.0);
  return plan;
}

bool has_vertex_at(const SolidMesh& mesh, double x, double y) {
  for (const auto v : mesh.vertices())
    if (mesh.point(v)[0] == x && mesh.point(v)[1] == y) return true;
  return false;
}

TEST(FuseSeams, SeamOfCollinearWallsOfOneColourHasNoVertex) {
  const Color grey{0x80, 0x80, 0x80};
  const Plan plan = collinear_tee(grey, grey);
  test::expect_paths_agree(plan, 1, 0.2 * 2.5 * (8 + 2.9) - 0.2 * 1.5 * 1.0);
  EXPECT_FALSE(has_vertex_at(build_model(plan).walls, 4.0, -0.1));
}

TEST(FuseSeams, SeamOfWallsOfTwoColoursKeepsItsVertex) {
  const Plan plan = collinear_tee({0xe0, 0x80, 0x20}, {0x80, 0x80, 0x80});
  test::expect_paths_agree(plan, 1, 0.2 * 2.5 * (8 + 2.9) - 0.2 * 1.5 * 1.0);
  EXPECT_TRUE(has_vertex_at(build_model(plan).walls, 4.0, -0.1));
}

// Faces of the general path (with vertex numbers) are never fused, and a seam point dropped
// from them takes its vertex number along, so the numbers still match the corners.
TEST(FuseSeams, SeamPointLeavesTheVertexNumbersOfGeneralFacesInStep) {
  using V = OpenMesh::Vec3d;
  detail::SoupFace below{{V(-1, -1, 0), V(1, -1, 0), V(1, 0, 0), V(0, 0, 0), V(-1, 0, 0)},
                         FaceKind::wall_top,
                         0,
                         {},
                         {},
                         {0, 1, 2, 3, 4}};
  detail::SoupFace above{{V(-1, 0, 0), V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(-1, 1, 0)},
                         FaceKind::wall_top,
                         0,
                         {},
                         {},
                         {4, 3, 2, 5, 6}};
  std::vector<detail::FaceSoup> soups{{below, above}};
  const std::vector<V> seam{V(0, 0, 0)};
  detail::fuse_seams(soups, seam);
  ASSERT_EQ(soups[0].size(), 2u);  // not fused
  EXPECT_EQ(soups[0][0].points,
            (std::vector<V>{V(-1, -1, 0), V(1, -1, 0), V(1, 0, 0), V(-1, 0, 0)}));
  EXPECT_EQ(soups[0][0].vertices, (std::vector<std::uint32_t>{0, 1, 2, 4}));
  EXPECT_EQ(soups[0][1].points, (std::vector<V>{V(-1, 0, 0), V(1, 0, 0), V(1, 1, 0), V(-1, 1, 0)}));
  EXPECT_EQ(soups[0][1].vertices, (std::vector<std::uint32_t>{4, 2, 5, 6}));
}

// The target: no more triangles than CGAL's Nef polyhedra (7,292 for 10 x 10).
TEST(FuseSeams, TenByTenGridHasNoMoreTrianglesThanNef) {
  const Plan plan = samples::make_grid_plan(samples::GridSpec{});
  const SolidCheck check = check_solid(build_model(plan).walls);
  EXPECT_TRUE(check.is_valid());
  EXPECT_LE(check.triangles, 7292u);
}

}  // namespace
}  // namespace roomcad
