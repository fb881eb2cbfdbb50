// SPDX-License-Identifier: GPL-3.0-or-later
// Slabs built with the walls (docs/plan-format.md "Version 2", slab_frames.h, slab_edges.h):
// one closed solid, the holes of the slab's area kept, a floor drawn to the walls' faces laid
// into them, the faces named after the slab.
#include <gtest/gtest.h>

#include <set>

#include "model_support.h"

namespace roomcad {
namespace {

using test::add_room;
using test::add_wall;
using test::empty_plan;
using test::expect_valid_walls;

// A 5 x 4 room (walls 0.2 thick, 2.7 high, mitred) under a slab 0.2 thick whose top is the
// walls' top: the outline 5.2 x 4.2 covers the walls, a stair well 1 x 2 inside.
Plan covered_room() {
  Plan plan = empty_plan();
  add_room(plan, "r", 1, 1, 5, 4);
  for (Wall& w : plan.walls) w.height = 2.7;
  Slab s;
  s.id = "lid";
  s.outline = {{0.9, 0.9}, {6.1, 0.9}, {6.1, 5.1}, {0.9, 5.1}};
  s.holes = {{{2, 2}, {3, 2}, {3, 4}, {2, 4}}};
  s.top = 2.7, s.thickness = 0.2;
  plan.slabs.push_back(s);
  return plan;
}

TEST(SlabBuild, ASlabAndTheWallsItMeetsAreOneClosedSolid) {
  // Walls: 0.2 x 18 (centre line) x 2.7 = 9.72; slab: (5.2 x 4.2 - 1 x 2) x 0.2 = 3.968; the
  // slab's bottom 0.2 over the walls' plan area (3.6 m^2) is counted once: - 0.72.
  // A lid with a stair well: genus 1 (the ring of walls is closed by the lid).
  for (const BooleanPath path : {BooleanPath::automatic, BooleanPath::general})
    expect_valid_walls(covered_room(), path, 1, 9.72 + 3.968 - 0.72);
}

TEST(SlabBuild, FacesOfTheSlabNameItAfterTheWallsAndOpenings) {
  const Model model = build_model(covered_room());
  ASSERT_EQ(model.objects.size(), 5u);
  EXPECT_EQ(model.objects[4], "lid");
  const FacePropertyHandles props = face_property_handles(model.walls);
  std::set<int> slab_objects;
  for (const auto f : model.walls.faces())
    if (model.walls.property(props.kind, f) == FaceKind::slab) slab_objects.insert(model.walls.property(props.object, f));
  EXPECT_EQ(slab_objects, std::set<int>{4});
}

TEST(SlabBuild, AFloorDrawnToTheWallsFacesIsLaidIntoThemNotLeftOnASliver) {
  // An upper storey's walls reach down through its floor (as Sweet Home 3D draws them), the
  // floor drawn to their inner faces at x = 3.2872205 + 0.13, which no double holds: within
  // rounding of the side, a sliver away from it. Laid into the walls, the floor joins them
  // face to face: the walls (0.26 x 4 x 2.74 each, 4 x 3 centre-line room, mitred: 0.26 x 14
  // x 2.74) and the floor inside them ((4 - 0.26) x (3 - 0.26) x 0.12) make one solid.
  Plan plan = empty_plan();
  add_room(plan, "u", 3.2872205, 1, 4, 3);
  for (Wall& w : plan.walls) w.thickness = 0.26, w.base = 2.5, w.height = 2.74;
  const double x0 = 3.2872205 + 0.13, x1 = 3.2872205 + 4 - 0.13;
  Slab s;
  s.id = "floor";
  s.outline = {{x0, 1.13}, {x1, 1.13}, {x1, 3.87}, {x0, 3.87}};
  s.top = 2.62, s.thickness = 0.12;
  plan.slabs.push_back(s);
  expect_valid_walls(plan, BooleanPath::automatic, 0, 0.26 * 14 * 2.74 + (4 - 0.26) * (3 - 0.26) * 0.12);
}

TEST(SlabBuild, AnOutlineThatCrossesItselfIsRefusedNamingTheSlab) {
  Plan plan = covered_room();
  plan.slabs[0].outline = {{0.9, 0.9}, {6.1, 5.1}, {6.1, 0.9}, {0.9, 5.1}};  // a bow tie
  test::expect_build_refused(plan, {}, Code::not_buildable, "slab 'lid'");
}

TEST(SlabBuild, TheNefPathRefusesSlabsByName) {
  test::expect_build_refused(covered_room(), test::options_for(BooleanPath::nef), Code::not_buildable, "slab 'lid'");
}

}  // namespace
}  // namespace roomcad
