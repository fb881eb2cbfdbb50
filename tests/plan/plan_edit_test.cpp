// SPDX-License-Identifier: GPL-3.0-or-later
// Plan edits: what each changes, what each refuses, and the exact round trips.
#include "plan/plan_edit.h"

#include <gtest/gtest.h>

#include "solid/build_model.h"
#include "testing/plan_builders.h"

namespace roomcad {
namespace {

/// A small room with decimal coordinates: two walls, a door, a window, a light, a camera.
Plan sample_plan() {
  Plan plan;
  plan.walls = {samples::make_wall("south", {1.1, 1.3}, {9.7, 1.3}, 0.25, 2.8),
                samples::make_wall("west", {1.1, 1.3}, {1.1, 6.45}, 0.25, 2.8)};
  Opening door = default_opening(OpeningType::door);
  door.id = "entry";
  door.wall = "south";
  door.offset = 1.5;
  Opening window = default_opening(OpeningType::window);
  window.id = "win";
  window.wall = "west";
  window.offset = 2.05;
  plan.openings = {door, window};
  Light sun;
  sun.id = "sun";
  plan.lights = {sun};
  Camera cam;
  cam.id = "view";
  cam.eye = {16.2, -9.1, 10};
  cam.target = {6.3, 4.7, 1};
  plan.cameras = {cam};
  return plan;
}

TEST(PlanEdit, AddGeneratesIdsUniqueAcrossAllObjects) {
  Plan plan = sample_plan();
  Light l;
  l.id = "wall-1";  // an id of the wall pattern held by another kind still counts
  add_light(plan, l);
  const EditSummary s = add_wall(plan, samples::make_wall("", {2, 2}, {3, 2}, 0.25, 2.8));
  EXPECT_EQ(s.added, std::vector<std::string>{"wall-2"});
  EXPECT_EQ(plan.walls.back().id, "wall-2");
  Opening d = default_opening(OpeningType::window);
  d.wall = "south";
  EXPECT_EQ(add_opening(plan, d).added, std::vector<std::string>{"window-1"});
  EXPECT_EQ(plan.openings.back().sill, 0.9);  // the spec's window default
  EXPECT_EQ(add_camera(plan, Camera{}).added, std::vector<std::string>{"camera-1"});
}

TEST(PlanEdit, AddRefusesUsedIdsAndUnknownWalls) {
  Plan plan = sample_plan();
  const Plan before = plan;
  EXPECT_THROW(add_wall(plan, samples::make_wall("entry", {0, 0}, {1, 0}, 0.25, 2.8)),
               PreconditionError);
  Opening d = default_opening(OpeningType::door);
  d.wall = "nowhere";
  try {
    add_opening(plan, d);
    FAIL() << "no throw";
  } catch (const PreconditionError& e) {
    EXPECT_NE(std::string(e.what()).find("'nowhere'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(plan, before);
}

TEST(PlanEdit, RemoveRefusesAWallWithOpeningsUnlessCascade) {
  Plan plan = sample_plan();
  const Plan before = plan;
  try {
    remove_object(plan, "south");
    FAIL() << "no throw";
  } catch (const PreconditionError& e) {
    EXPECT_NE(std::string(e.what()).find("entry"), std::string::npos) << e.what();
  }
  EXPECT_EQ(plan, before);
  const EditSummary s = remove_object(plan, "south", {.cascade = true});
  EXPECT_EQ(s.removed, (std::vector<std::string>{"south", "entry"}));
  EXPECT_EQ(plan.walls.size(), 1u);
  EXPECT_EQ(plan.openings.size(), 1u);
  EXPECT_EQ(remove_object(plan, "view").removed, std::vector<std::string>{"view"});
  EXPECT_TRUE(plan.cameras.empty());
  EXPECT_THROW(remove_object(plan, "ghost"), PreconditionError);
}

TEST(PlanEdit, MovingAWallCarriesItsOpeningsAndMovesBackExactly) {
  Plan plan = sample_plan();
  const Plan before = plan;
  const EditSummary s = move_object(plan, "south", {0.1, -0.3});
  EXPECT_EQ(s.changed, std::vector<std::string>{"south"});
  EXPECT_EQ(plan.walls[0].from, (Point2{1.2, 1.0}));  // correctly rounded decimals
  EXPECT_EQ(plan.openings, before.openings);          // relative to the wall: unchanged
  move_object(plan, "south", {-0.1, 0.3});
  EXPECT_EQ(plan, before);
}

TEST(PlanEdit, AnOpeningSlidesAlongItsWall) {
  Plan plan = sample_plan();
  EXPECT_EQ(slide_opening(plan, "entry", 0.2).changed, std::vector<std::string>{"entry"});
  EXPECT_EQ(plan.openings[0].offset, 1.7);
  slide_opening(plan, "entry", -0.2);
  EXPECT_EQ(plan, sample_plan());
  EXPECT_THROW(slide_opening(plan, "south", 1.0), PreconditionError);
  EXPECT_THROW(move_object(plan, "entry", {1.0, 0.0}), PreconditionError);
  EXPECT_THROW(move_object(plan, "sun", {1.0, 0.0}), PreconditionError);
}

TEST(PlanEdit, RotateAWallAboutItsMidpointByDefault) {
  Plan plan = sample_plan();
  rotate_object(plan, "south", 90.0);
  EXPECT_EQ(plan.walls[0].from, (Point2{5.4, -3.0}));
  EXPECT_EQ(plan.walls[0].to, (Point2{5.4, 5.6}));
  for (int i = 0; i < 3; ++i) rotate_object(plan, "south", 90.0);
  EXPECT_EQ(plan, sample_plan());
  EXPECT_THROW(rotate_object(plan, "entry", 90.0), PreconditionError);
}

TEST(PlanEdit, RotateTurnsLightDirectionsAndCameras) {
  Plan plan = sample_plan();
  rotate_object(plan, "sun", 90.0);
  EXPECT_EQ(plan.lights[0].direction, (Vec3{-0.5, -0.4, -1.0}));
  rotate_object(plan, "view", 180.0);  // about its target: the eye goes to the other side
  EXPECT_EQ(plan.cameras[0].target, sample_plan().cameras[0].target);
  EXPECT_EQ(plan.cameras[0].eye, (Vec3{-3.6, 18.5, 10}));
  EXPECT_EQ(plan.cameras[0].up, (Vec3{0, 0, 1}));
}

TEST(PlanEdit, ScaleAWallScalesItsOpeningsAlongItButNotHeightsOrThickness) {
  Plan plan = sample_plan();
  scale_object(plan, "south", 2.0, Point2{1.1, 1.3});
  EXPECT_EQ(plan.walls[0].from, (Point2{1.1, 1.3}));
  EXPECT_EQ(plan.walls[0].to, (Point2{18.3, 1.3}));
  EXPECT_EQ(plan.walls[0].thickness, 0.25);
  EXPECT_EQ(plan.openings[0].offset, 3.0);
  EXPECT_EQ(plan.openings[0].width, 1.8);
  EXPECT_EQ(plan.openings[0].height, 2.1);
  EXPECT_EQ(plan.openings[1], sample_plan().openings[1]);  // another wall's window
  scale_object(plan, "south", 0.5, Point2{1.1, 1.3});
  EXPECT_EQ(plan, sample_plan());
  EXPECT_THROW(scale_object(plan, "south", 0.0), PreconditionError);
  EXPECT_THROW(scale_object(plan, "south", -1.0), PreconditionError);
  EXPECT_THROW(scale_object(plan, "sun", 2.0), PreconditionError);
}

TEST(PlanEdit, FourQuarterTurnsOfTheWholePlanAreIdentity) {
  Plan plan = sample_plan();
  plan.site.origin = {0.3, -0.7};
  plan.site.cells = {13, 9};
  plan.site.cell_size = 0.9;
  const Plan before = plan;
  rotate_all(plan, 90.0);
  EXPECT_EQ(plan.site.cells, (std::array<std::int64_t, 2>{9, 13}));
  EXPECT_NE(plan, before);
  for (int i = 0; i < 3; ++i) rotate_all(plan, 90.0);
  EXPECT_EQ(plan, before);
}

TEST(PlanEdit, AQuarterTurnOfTheWholePlanKeepsItInItsSite) {
  Plan plan = sample_plan();
  plan.site.cells = {12, 8};
  rotate_all(plan, 90.0);  // about the site's centre (6, 4): the site becomes [2, 10] x [-2, 10]
  EXPECT_EQ(plan.site.origin, (Point2{2.0, -2.0}));
  EXPECT_EQ(plan.walls[0].from, (Point2{8.7, -0.9}));
  rotate_all(plan, 30.0);  // not a quarter turn: the site stays
  EXPECT_EQ(plan.site.origin, (Point2{2.0, -2.0}));
}

TEST(PlanEdit, MoveAndScaleAllTakeTheSiteAlong) {
  Plan plan = sample_plan();
  const EditSummary s = move_all(plan, {0.5, 0.25});
  EXPECT_EQ(s.changed, (std::vector<std::string>{"site", "south", "west", "view"}));
  EXPECT_EQ(plan.site.origin, (Point2{0.5, 0.25}));
  move_all(plan, {-0.5, -0.25});
  EXPECT_EQ(plan, sample_plan());
  scale_all(plan, 2.0, Point2{0, 0});
  EXPECT_EQ(plan.site.cell_size, 2.0);
  EXPECT_EQ(plan.walls[1].to, (Point2{2.2, 12.9}));
  EXPECT_EQ(plan.openings[1].offset, 4.1);
  scale_all(plan, 0.5, Point2{0, 0});
  EXPECT_EQ(plan, sample_plan());
}

TEST(PlanEdit, SetFieldIsTypeChecked) {
  Plan plan = sample_plan();
  EXPECT_EQ(set_field(plan, "south", "thickness", "0.3")->changed,
            std::vector<std::string>{"south"});
  EXPECT_EQ(plan.walls[0].thickness, 0.3);
  ASSERT_TRUE(set_field(plan, "south", "color", "#102030").ok());
  EXPECT_EQ(plan.walls[0].color, (Color{0x10, 0x20, 0x30}));
  ASSERT_TRUE(set_field(plan, "entry", "hinge", "right").ok());
  EXPECT_EQ(plan.openings[0].hinge, Hinge::right);
  ASSERT_TRUE(set_field(plan, "view", "up", "0, 1, 0").ok());
  EXPECT_EQ(plan.cameras[0].up, (Vec3{0, 1, 0}));
  ASSERT_TRUE(set_field(plan, "site", "cells", "20,10").ok());
  EXPECT_EQ(plan.site.cells, (std::array<std::int64_t, 2>{20, 10}));
  EXPECT_TRUE(set_field(plan, "south", "height", "2.8")->changed.empty());  // same value
}

/// The error an edit returns or throws (make_edit; Code::internal with no message if none).
template <class Edit>
Error refusal(Edit edit) {
  Plan unused;
  const Result<EditSummary> made = make_edit([&](Plan&) { return edit(); }, unused);
  return made.ok() ? Error{} : made.error();
}

TEST(PlanEdit, SetFieldErrorsNameObjectKeyAndValue) {
  Plan plan = sample_plan();
  const Plan before = plan;
  EXPECT_EQ(
      refusal([&] { return set_field(plan, "south", "colour", "#ffffff"); }),
      Error(Code::usage_error, "set: wall 'south' has no field 'colour' (did you mean 'color'?)"));
  EXPECT_EQ(
      refusal([&] { return set_field(plan, "south", "thickness", "thick"); }),
      Error(Code::usage_error, "set: wall 'south' field 'thickness' wants metres, got 'thick'"));
  EXPECT_EQ(
      refusal([&] { return set_field(plan, "entry", "swing", "sideways"); }),
      Error(Code::usage_error, "set: door 'entry' field 'swing' wants in or out, got 'sideways'"));
  EXPECT_NE(refusal([&] {
              return set_field(plan, "view", "zzzz", "1");
            }).message.find("fields: id, projection"),
            std::string::npos);
  const Error nobody = refusal([&] { return set_field(plan, "nobody", "id", "x"); });
  EXPECT_EQ(nobody.code, Code::precondition);
  EXPECT_NE(nobody.message.find("no object has id 'nobody'"), std::string::npos);
  EXPECT_EQ(refusal([&] { return set_field(plan, "south", "height", "nan"); }).code,
            Code::usage_error);
  EXPECT_EQ(refusal([&] { return set_field(plan, "south", "from", "1,2,3"); }).code,
            Code::usage_error);
  EXPECT_EQ(plan, before);
}

TEST(PlanEdit, RenamingAWallRenamesItsOpeningsReferences) {
  Plan plan = sample_plan();
  const EditSummary s = set_field(plan, "south", "id", "front").value();
  EXPECT_EQ(s.changed, (std::vector<std::string>{"front", "entry"}));
  EXPECT_EQ(plan.openings[0].wall, "front");
  EXPECT_EQ(set_field(plan, "front", "id", "west").code(), Code::precondition);
}

TEST(PlanEdit, FieldNamesFollowTheFormat) {
  EXPECT_EQ(field_names("wall"),
            (std::vector<std::string_view>{"id", "level", "from", "to", "thickness", "height",
                                           "base", "height_at_end", "arc_extent", "color"}));
  EXPECT_EQ(field_names("slab"), (std::vector<std::string_view>{"id", "level", "outline", "holes",
                                                                "top", "thickness", "color"}));
  EXPECT_EQ(object_kind(sample_plan(), "win"), "window");
  EXPECT_EQ(object_kind(sample_plan(), "nothing"), std::nullopt);
}

}  // namespace
}  // namespace roomcad
