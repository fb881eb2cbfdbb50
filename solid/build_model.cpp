// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/build_model.h"

#include <chrono>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "geometry/joins.h"
#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/assembly/floor_fixtures.h"
#include "solid/detail/cells/find_cells.h"
#include "solid/detail/fast_path/fast_wall.h"
#include "solid/detail/fast_path/fuse_seams.h"
#include "solid/detail/frames/buildable_plan.h"
#include "solid/detail/frames/clusters.h"
#include "solid/detail/frames/fine_features.h"
#include "solid/detail/frames/wall_frame.h"
#include "solid/detail/general_path/general_solid.h"
#include "solid/detail/nef/cgal_booleans.h"
#include "solid/wall_check.h"

namespace roomcad {
namespace {

using detail::FaceSoup;
using detail::WallFrame;
using detail::WorkItem;

// The walls and slabs a build works on.
struct Frames {
  const std::vector<WallFrame>& walls;
  const std::vector<detail::SlabFrame>& slabs;
};

FaceSoup build_item(const Plan& plan, const Frames& frames, const detail::Work& work,
                    const WorkItem& item, const BuildOptions& options) {
  const BooleanPath path = options.boolean;
  const int first_opening = detail::opening_object(plan, 0);
  if (item.kind == WorkItem::Kind::hub)
    return detail::build_hub(work.hubs[item.hub], work.fast_frames);
  if (item.kind == WorkItem::Kind::fast_wall) {
    const WallFrame& f = work.fast_frames[item.walls.front()];
    return detail::build_fast_wall(f, static_cast<int>(f.wall), first_opening);
  }
  std::vector<const WallFrame*> walls;
  walls.reserve(item.walls.size());
  for (std::size_t i : item.walls) walls.push_back(&frames.walls[i]);
  std::vector<const detail::SlabFrame*> slabs;
  for (std::size_t i : item.slabs) slabs.push_back(&frames.slabs[i]);
  if (uses_nef(path)) {
    if (!slabs.empty())
      throw PreconditionError(
          fmt::format("build_model: slab '{}' is not built by the Nef path (--boolean nef); "
                      "the default path builds slabs",
                      plan.slabs[slabs.front()->slab].id),
          Code::not_buildable);
    return detail::build_cluster_cgal(walls, first_opening);
  }
  return detail::build_cluster_general(walls, slabs, first_opening, detail::slab_object(plan, 0),
                                       options.grid_planes);
}

// Builds every item in parallel; results land in item order, so the mesh does not depend on
// the thread count.
std::vector<FaceSoup> build_items(const Plan& plan, const Frames& frames, const detail::Work& work,
                                  const BuildOptions& options) {
  std::vector<FaceSoup> soups(work.items.size());
  tbb::parallel_for(std::size_t{0}, work.items.size(), [&](std::size_t i) {
    soups[i] = build_item(plan, frames, work, work.items[i], options);
  });
  return soups;
}

// Builds the wall items, then fuses the fast path's faces across the seams of its hubs.
std::vector<FaceSoup> build_walls(const Plan& plan, const Frames& frames, const detail::Work& work,
                                  const BuildOptions& options) {
  std::vector<FaceSoup> soups = build_items(plan, frames, work, options);
  std::vector<detail::Hub> hubs;
  for (const WorkItem& item : work.items)
    if (item.kind == WorkItem::Kind::hub) hubs.push_back(work.hubs[item.hub]);
  detail::fuse_seams(soups, detail::find_seam_points(hubs, work.fast_frames));
  return soups;
}

// Leaves out of the work the slabs (--parts without slabs) or the walls (without walls).
void keep_parts(detail::Work& work, const Parts& parts) {
  for (WorkItem& item : work.items) {
    if (!parts.slabs) item.slabs.clear();
    if (!parts.walls) item.walls.clear();
  }
  std::erase_if(work.items, [&](const WorkItem& item) {
    return item.kind == WorkItem::Kind::hub ? !parts.walls
                                            : item.walls.empty() && item.slabs.empty();
  });
}

// A plan with a feature finer than its doubles resolve (fine_features.h) builds only if its
// solid as written passes the check of `build --check`; else it is refused, naming the feature.
void require_written_solid(const Model& model, const Plan& plan, const std::string& feature) {
  const WallCheck check = check_walls(model, plan);
  if (check.ok) return;
  throw PreconditionError(
      fmt::format("build_model: the solid fails once its corners are rounded to doubles ({}), as "
                  "it can where features are under {} m or coordinates past {} m: {}; make every "
                  "feature at least {} m and keep the plan within {} m of the origin",
                  describe_failures(check), detail::kFinestFeature, detail::kFarthestCoordinate,
                  feature, detail::kFinestFeature, detail::kFarthestCoordinate),
      Code::not_buildable);
}

void count_paths(const std::vector<WorkItem>& items, BooleanPath path, BuildStats& stats) {
  std::size_t& cluster_walls = uses_nef(path) ? stats.nef_path_walls : stats.general_path_walls;
  for (const WorkItem& item : items)
    (item.kind == WorkItem::Kind::cluster ? cluster_walls : stats.fast_path_walls) +=
        item.walls.size();
}

}  // namespace

std::vector<std::string> model_object_ids(const Plan& plan) {
  std::vector<std::string> ids;
  ids.reserve(plan.walls.size() + plan.openings.size() + plan.slabs.size());
  for (const Wall& w : plan.walls) ids.push_back(w.id);
  for (const Opening& o : plan.openings) ids.push_back(o.id);
  for (const Slab& s : plan.slabs) ids.push_back(s.id);
  return ids;
}

Cells find_model_cells(const Plan& input, const Parts& parts) {
  if (!parts.walls) return {};
  const detail::BuildablePlan buildable = detail::make_buildable(input);
  const Joins joins = find_joins(buildable.plan);
  return detail::find_cells(
      buildable.plan, detail::make_wall_frames(buildable.plan, joins, buildable.through_mitre),
      parts.slabs);
}

Model build_model(const Plan& input, const BuildOptions& options, BuildStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<tbb::global_control> limit;
  if (options.threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
  std::vector<std::string> objects = model_object_ids(input);
  const detail::BuildablePlan buildable = detail::make_buildable(input);
  const Plan& plan = buildable.plan;
  const Joins joins = find_joins(plan);
  const std::vector<WallFrame> frames =
      detail::make_wall_frames(plan, joins, buildable.through_mitre);
  BuildStats local;
  std::vector<FaceSoup> walls;
  if (options.parts.walls || options.parts.slabs) {
    const std::vector<detail::SlabFrame> slabs = detail::make_slab_frames(plan, frames);
    detail::Work work = detail::plan_work(frames, joins, options.boolean, slabs);
    keep_parts(work, options.parts);
    count_paths(work.items, options.boolean, local);
    walls = build_walls(plan, {frames, slabs}, work, options);
    detail::label_input_objects(buildable, walls);
  }
  const FaceSoup floor = options.parts.floor ? detail::build_floor(plan.site) : FaceSoup{};
  std::vector<FaceSoup> fixtures =
      options.parts.fixtures ? detail::build_fixtures(plan, frames) : std::vector<FaceSoup>{};
  detail::label_input_objects(buildable, fixtures);
  // Each mesh is made in place: an OpenMesh mesh has no move constructor (its kernel declares
  // a destructor), so assigning one to a member would copy it.
  Model model{.walls = detail::assemble_mesh(walls, objects),
              .floor = detail::assemble_mesh({&floor, 1}, objects),
              .fixtures = detail::assemble_mesh(fixtures, objects, false),
              .objects = std::move(objects),
              .slabs_built = options.parts.slabs};
  detail::require_closed(model.walls, model.objects);
  if (options.cells && options.parts.walls)
    model.cells = detail::find_cells(plan, frames, options.parts.slabs);
  if (options.parts.walls)
    if (const auto fine = detail::fine_feature(input)) require_written_solid(model, input, *fine);
  local.build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (stats != nullptr) *stats = local;
  return model;
}

}  // namespace roomcad
