// SPDX-License-Identifier: GPL-3.0-or-later
// A facet of the CGAL path that spans walls of different colours is labelled as one piece:
// no colour boundary runs diagonally across it.
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "support/model_support.h"

namespace roomcad {
namespace {

// Wall A (orange) and wall B (grey) collinear along y = 0, joined at x = 4 by stem C; a
// window in B puts a hole in the merged front facet, which CGAL then triangulates.
Plan two_colour_tee() {
  Plan plan = test::empty_plan();
  test::add_wall(plan, "a", {0, 0}, {4, 0}).color = Color{0xe0, 0x80, 0x20};
  test::add_wall(plan, "b", {4, 0}, {8, 0}).color = Color{0x80, 0x80, 0x80};
  test::add_wall(plan, "c", {4, 0}, {4, 3});
  test::add_opening(plan, "win", OpeningType::window, "b", 1.0, 1.5, 0.9, 1.0);
  return plan;
}

TEST(FacetLabels, MergedFacetHasOneColour) {
  const Plan plan = two_colour_tee();
  test::expect_valid_walls(plan, BooleanPath::nef, 1);
  const Model model = build_model(plan, test::options_for(BooleanPath::nef));
  const FacePropertyHandles props = face_property_handles(model.walls);
  std::set<std::tuple<int, int, int>> front_colours;
  std::size_t front_faces = 0;
  for (const auto f : model.walls.faces()) {
    const OpenMesh::Vec3d n = model.walls.calc_face_normal(f);
    if (n[1] > -0.99 || model.walls.property(props.kind, f) != FaceKind::wall_face) continue;
    const Color c = model.walls.property(props.color, f);
    front_colours.emplace(c.r, c.g, c.b);
    ++front_faces;
  }
  EXPECT_GT(front_faces, 2u) << "the front facet should come triangulated around the window";
  EXPECT_EQ(front_colours.size(), 1u);
}

}  // namespace
}  // namespace roomcad
