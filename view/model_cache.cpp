// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/model_cache.h"

#include <memory>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "view/wall_groups.h"

namespace roomcad {
namespace {

/// One group of walls as a plan of its own, and where its objects are in the whole plan.
struct GroupPlan {
  Plan plan;
  std::vector<int> objects;  ///< the whole plan's object index of each of the group's objects
};

/// @return the plan holding only `walls` (indices into plan.walls) and their openings (every
///         opening when `walls` are all of them), with the whole plan's site, levels and slabs.
GroupPlan group_plan(const Plan& plan, const std::vector<std::size_t>& walls) {
  GroupPlan group;
  group.plan.site = plan.site;
  group.plan.levels = plan.levels;
  group.plan.slabs = plan.slabs;  // none unless the group is the whole plan (wall_groups.h)
  group.plan.extra = plan.extra;
  std::unordered_set<std::string_view> ids;
  for (std::size_t i : walls) {
    group.plan.walls.push_back(plan.walls[i]);
    group.objects.push_back(static_cast<int>(i));
    ids.insert(plan.walls[i].id);
  }
  const bool whole = walls.size() == plan.walls.size();
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    if (!whole && ids.count(plan.openings[i].wall) == 0) continue;
    group.plan.openings.push_back(plan.openings[i]);
    group.objects.push_back(static_cast<int>(plan.walls.size() + i));
  }
  return group;
}

/// True when builds with these options give the same model (the thread count never matters).
bool is_same_output(const BuildOptions& a, const BuildOptions& b) {
  return a.boolean == b.boolean && a.parts.walls == b.parts.walls &&
         a.parts.floor == b.parts.floor && a.parts.fixtures == b.parts.fixtures;
}

/// Appends the faces of `from` to `into` with their vertices (shared as they are in `from`),
/// normals, kinds and colours, each face's object mapped through `objects` (-1 stays -1).
/// @pre add_face_properties was called on both meshes. O(vertices + corners).
void append_solid(const SolidMesh& from, const std::vector<int>& objects, SolidMesh& into) {
  const FacePropertyHandles source = face_property_handles(from);
  const FacePropertyHandles target = face_property_handles(into);
  std::vector<SolidMesh::VertexHandle> vertex_of(from.n_vertices());
  for (const SolidMesh::VertexHandle v : from.vertices())
    vertex_of[v.idx()] = into.add_vertex(from.point(v));
  std::vector<SolidMesh::VertexHandle> corners;
  for (const SolidMesh::FaceHandle f : from.faces()) {
    corners.clear();
    for (const SolidMesh::VertexHandle v : from.fv_range(f)) corners.push_back(vertex_of[v.idx()]);
    const SolidMesh::FaceHandle added = into.add_face(corners);
    const int object = from.property(source.object, f);
    into.property(target.object, added) = object < 0 ? object : objects.at(object);
    into.property(target.kind, added) = from.property(source.kind, f);
    into.property(target.color, added) = from.property(source.color, f);
    into.set_normal(added, from.normal(f));
  }
}

}  // namespace

std::shared_ptr<const ModelCache::Entry> ModelCache::find_or_build(Plan group,
                                                                   const BuildOptions& options) {
  const auto cached = by_first_wall_.find(group.walls.front().id);
  if (cached != by_first_wall_.end() && cached->second->plan == group) return cached->second;
  BuildOptions walls_and_fixtures = options;
  walls_and_fixtures.parts.floor = false;  // built once for the whole site
  Model built = build_model(group, walls_and_fixtures);
  ++stats_.rebuilt;
  return std::make_shared<const Entry>(Entry{std::move(group), std::move(built)});
}

const SolidMesh& ModelCache::floor_of(const Site& site, const BuildOptions& options) {
  if (floor_site_ != site) {
    Plan bare;
    bare.site = site;
    BuildOptions floor_only = options;
    floor_only.parts = {.walls = false, .floor = true, .fixtures = false};
    floor_ = build_model(bare, floor_only).floor;
    floor_site_ = site;
    stats_.floor_rebuilt = true;
  }
  return floor_;
}

Model ModelCache::build(const Plan& plan, const BuildOptions& options) {
  if (!options_ || !is_same_output(*options_, options)) {
    by_first_wall_.clear();
    floor_site_.reset();
    options_ = options;
  }
  stats_ = {};
  Model model;
  model.objects = model_object_ids(plan);
  for (SolidMesh* mesh : {&model.walls, &model.floor, &model.fixtures}) add_face_properties(*mesh);
  std::unordered_map<std::string, std::shared_ptr<const Entry>> next;
  for (const std::vector<std::size_t>& walls : find_wall_groups(plan)) {
    GroupPlan group = group_plan(plan, walls);
    std::string first = group.plan.walls.front().id;
    std::shared_ptr<const Entry> entry = find_or_build(std::move(group.plan), options);
    append_solid(entry->model.walls, group.objects, model.walls);
    append_solid(entry->model.fixtures, group.objects, model.fixtures);
    next.emplace(std::move(first), std::move(entry));
    ++stats_.groups;
  }
  if (options.parts.floor) append_solid(floor_of(plan.site, options), {}, model.floor);
  by_first_wall_ = std::move(next);  // only now: a build that throws leaves the cache as it was
  return model;
}

}  // namespace roomcad
