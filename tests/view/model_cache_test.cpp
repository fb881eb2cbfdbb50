// SPDX-License-Identifier: GPL-3.0-or-later
// The window's model cache (view/model_cache.h): after every kind of edit its model is the
// model build_model makes of the whole plan (the same faces with the same corners, objects,
// kinds, colours and normals, the same vertices and edges), while it rebuilds only the wall
// groups the edit touched.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "io/plan_json.h"
#include "support/run_command.h"
#include "view/model_cache.h"
#include "view/wall_groups.h"

namespace roomcad {
namespace {

using Corner = std::array<double, 3>;
/// A face told apart from its place in the mesh: corners from the smallest one on (the
/// order kept), object id, kind, colour and normal.
using Face = std::tuple<std::vector<Corner>, std::string, int, std::array<int, 3>, Corner>;

std::vector<Face> faces_of(const SolidMesh& mesh, const std::vector<std::string>& objects) {
  const FacePropertyHandles props = face_property_handles(mesh);
  std::vector<Face> faces;
  for (const SolidMesh::FaceHandle f : mesh.faces()) {
    std::vector<Corner> corners;
    for (const SolidMesh::VertexHandle v : mesh.fv_range(f))
      corners.push_back({mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2]});
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    const int object = mesh.property(props.object, f);
    const Color c = mesh.property(props.color, f);
    const OpenMesh::Vec3d n = mesh.normal(f);
    faces.emplace_back(std::move(corners), object < 0 ? "" : objects.at(object),
                       static_cast<int>(mesh.property(props.kind, f)),
                       std::array<int, 3>{c.r, c.g, c.b}, Corner{n[0], n[1], n[2]});
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

/// Expects the two meshes to be one mesh up to the order of faces and vertices.
void expect_same_mesh(const Model& got, const Model& want, const SolidMesh Model::*part,
                      const char* name) {
  const SolidMesh& a = got.*part;
  const SolidMesh& b = want.*part;
  EXPECT_EQ(a.n_vertices(), b.n_vertices()) << name;
  EXPECT_EQ(a.n_edges(), b.n_edges()) << name;
  const std::vector<Face> fa = faces_of(a, got.objects), fb = faces_of(b, want.objects);
  ASSERT_EQ(fa.size(), fb.size()) << name;
  const auto [x, y] = std::mismatch(fa.begin(), fa.end(), fb.begin());
  EXPECT_TRUE(x == fa.end()) << name << ": face " << (x - fa.begin()) << " of " << fa.size()
                             << " differs (object '" << std::get<1>(*x) << "' vs '"
                             << std::get<1>(*y) << "')";
}

/// Builds `plan` through the cache and expects build_model's model of it.
ModelCacheStats expect_full_build(ModelCache& cache, const Plan& plan) {
  const Model got = cache.build(plan, {});
  const Model want = build_model(plan);
  EXPECT_EQ(got.objects, want.objects);
  expect_same_mesh(got, want, &Model::walls, "walls");
  expect_same_mesh(got, want, &Model::floor, "floor");
  expect_same_mesh(got, want, &Model::fixtures, "fixtures");
  return cache.last_stats();
}

Plan example(const std::string& name) {
  return read_plan_file(test::source_dir() / "examples" / name).value();
}

/// A row of `n` square rooms 3 m wide, 1 m apart, each with a door in its south wall.
Plan row_of_rooms(int n) {
  Plan plan;
  plan.site.cells = {4 * n + 1, 5};
  for (int k = 0; k < n; ++k) {
    const double x = 0.5 + 4.0 * k;
    const std::array<Point2, 4> c{{{x, 1}, {x + 3, 1}, {x + 3, 4}, {x, 4}}};
    for (int side = 0; side < 4; ++side) {
      Wall& w = plan.walls.emplace_back();
      w.id = fmt::format("r{}-{}", k, side), w.from = c[side], w.to = c[(side + 1) % 4];
      w.thickness = 0.2;
    }
    Opening& door = plan.openings.emplace_back();
    door.id = fmt::format("door{}", k), door.wall = fmt::format("r{}-0", k), door.offset = 1;
  }
  return plan;
}

void move_wall(Plan& plan, std::size_t wall, double dx, double dy) {
  Wall& w = plan.walls[wall];
  w.from = {w.from.x + dx, w.from.y + dy}, w.to = {w.to.x + dx, w.to.y + dy};
}

TEST(ModelCache, EachEditRebuildsOnlyTheRoomItTouchesAndEqualsAFullBuild) {
  Plan plan = row_of_rooms(4);
  ModelCache cache;
  ModelCacheStats s = expect_full_build(cache, plan);
  EXPECT_EQ(s.groups, 4u);
  EXPECT_EQ(s.rebuilt, 4u);
  EXPECT_TRUE(s.floor_rebuilt);
  // The east wall of room 1 moves out by 0.5 m, its south and north walls stretched to it.
  move_wall(plan, 5, 0.5, 0.0), plan.walls[4].to.x += 0.5, plan.walls[6].from.x += 0.5;
  s = expect_full_build(cache, plan);
  EXPECT_EQ(s.groups, 4u);
  EXPECT_EQ(s.rebuilt, 1u);
  EXPECT_FALSE(s.floor_rebuilt);
  plan.openings[2].offset = 1.5;  // a door of room 2 moves
  EXPECT_EQ(expect_full_build(cache, plan).rebuilt, 1u);
  plan.walls[12].height = 3.1, plan.walls[13].color = Color{10, 20, 30};  // room 3, twice
  EXPECT_EQ(expect_full_build(cache, plan).rebuilt, 1u);
  plan.lights.push_back(default_light());
  EXPECT_EQ(expect_full_build(cache, plan).rebuilt, 0u);
  plan.site.floor_color = Color{1, 2, 3};  // the site: every group, and the floor
  s = expect_full_build(cache, plan);
  EXPECT_EQ(s.rebuilt, 4u);
  EXPECT_TRUE(s.floor_rebuilt);
}

TEST(ModelCache, GroupsThatMeetOrPartAfterAnEditEqualAFullBuild) {
  Plan plan = row_of_rooms(3);
  ModelCache cache;
  expect_full_build(cache, plan);
  // Room 0's east wall moves 0.8 m east against room 1's west wall: the rooms are one group.
  move_wall(plan, 1, 0.8, 0.0), plan.walls[0].to.x += 0.8, plan.walls[2].from.x += 0.8;
  ModelCacheStats s = expect_full_build(cache, plan);
  EXPECT_EQ(s.groups, 2u);
  EXPECT_EQ(s.rebuilt, 1u);
  move_wall(plan, 1, -0.8, 0.0), plan.walls[0].to.x -= 0.8, plan.walls[2].from.x -= 0.8;
  s = expect_full_build(cache, plan);
  EXPECT_EQ(s.groups, 3u);
  EXPECT_EQ(s.rebuilt, 2u);  // room 1 was only cached as part of the group of rooms 0 and 1
  plan.walls.erase(plan.walls.begin() + 9);  // room 2's east wall (its door is in the south)
  EXPECT_EQ(expect_full_build(cache, plan).rebuilt, 1u);
  plan.walls.erase(plan.walls.begin(), plan.walls.begin() + 4);  // room 0 and its door
  plan.openings.erase(plan.openings.begin());
  EXPECT_EQ(expect_full_build(cache, plan).rebuilt, 0u);  // the others' objects renumbered
}

TEST(ModelCache, EditsOfTheExamplesEqualAFullBuild) {
  for (const char* name : {"studio.json", "house.json", "sweethome3d/Sample.json"}) {
    SCOPED_TRACE(name);
    Plan plan = example(name);
    ModelCache cache;
    const std::size_t groups = expect_full_build(cache, plan).groups;
    for (const std::size_t i : {std::size_t{0}, plan.walls.size() / 2, plan.walls.size() - 1}) {
      SCOPED_TRACE(plan.walls[i].id);
      plan.walls[i].height += 0.25;
      const ModelCacheStats s = expect_full_build(cache, plan);
      EXPECT_EQ(s.groups, groups);
      EXPECT_EQ(s.rebuilt, 1u);
    }
    plan.openings.front().offset += 0.05;
    EXPECT_EQ(expect_full_build(cache, plan).rebuilt, 1u);
  }
}

TEST(ModelCache, AFailedBuildKeepsTheCache) {
  Plan plan = row_of_rooms(2);
  ModelCache cache;
  expect_full_build(cache, plan);
  Plan broken = plan;
  broken.openings[1].width = 10.0;  // wider than its wall: cannot be cut
  EXPECT_THROW((void)cache.build(broken, {}), PreconditionError);
  EXPECT_EQ(expect_full_build(cache, plan).rebuilt, 0u);
}

TEST(WallGroups, WallsJoinedOrTouchingAreOneGroup) {
  Plan plan = row_of_rooms(3);
  using Groups = std::vector<std::vector<std::size_t>>;
  EXPECT_EQ(find_wall_groups(plan), (Groups{{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}}));
  plan.walls[1].thickness = 1.8 - kGroupMargin;  // within kGroupMargin of room 1's west wall
  EXPECT_EQ(find_wall_groups(plan), (Groups{{0, 1, 2, 3, 4, 5, 6, 7}, {8, 9, 10, 11}}));
  plan.walls[1].thickness = 1.5;  // 0.15 m apart
  EXPECT_EQ(find_wall_groups(plan).size(), 3u);
  Wall lone;
  lone.id = "lone", lone.from = {2, 4.5}, lone.to = {10, 4.5}, lone.thickness = 0.1;
  plan.walls.insert(plan.walls.begin(), lone);  // crosses no wall, touches none: 4 groups
  EXPECT_EQ(find_wall_groups(plan).size(), 4u);
  plan.walls.front().thickness = 0.8;  // now over the north walls of rooms 0, 1 and 2
  EXPECT_EQ(find_wall_groups(plan).size(), 1u);
}

TEST(WallGroups, WhatFootprintsCannotTellIsOneGroup) {
  const Plan rooms = row_of_rooms(3);
  std::vector<Plan> plans(4, rooms);
  plans[0].walls[5].arc_extent = 30.0;
  plans[1].walls[5].to = plans[1].walls[5].from;  // zero length
  plans[2].walls[5].id = plans[2].walls[0].id;
  plans[3].openings[0].wall = "nowhere";
  for (const Plan& plan : plans) EXPECT_EQ(find_wall_groups(plan).size(), 1u);
  EXPECT_TRUE(find_wall_groups(Plan{}).empty());
}

}  // namespace
}  // namespace roomcad
