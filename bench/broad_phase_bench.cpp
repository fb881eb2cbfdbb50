// SPDX-License-Identifier: GPL-3.0-or-later
// The broad phase of the build's first stages on real homes and the 504-wall tower (Google
// Benchmark; never a timed test), one thread:
// - BM_WallPairs: the pairs of walls whose footprint boxes meet, in plan alone (`plan`: every
//   storey meets the ones above and below it) and in space (`space`: heights too, what
//   plan_work links walls by); counter pairs;
// - BM_FindJoins and BM_PlanWork: the two stages that read those pairs (joins.h, clusters.h).
// A multi-storey home drawn storey over storey (arif-putra-pertama-1, the tower) has several
// times more pairs in plan than in space.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "geometry/broad_phase.h"
#include "geometry/joins.h"
#include "io/plan_json.h"
#include "solid/detail/frames/buildable_plan.h"
#include "solid/detail/frames/clusters.h"
#include "solid/detail/frames/slab_frames.h"
#include "solid/detail/frames/wall_frame.h"
#include "testing/tower_plan.h"

namespace roomcad {
namespace {

// The plan as build_model reads it: imported homes from examples/sweethome3d/, or the tower.
detail::BuildablePlan buildable(const std::string& name) {
  if (name == "tower") return detail::make_buildable(samples::make_tower_plan({}));
  const auto file =
      std::filesystem::path(ROOMCAD_SOURCE_DIR) / "examples" / "sweethome3d" / (name + ".json");
  Result<Plan> plan = read_plan_file(file);
  if (!plan) throw std::runtime_error(plan.message());
  return detail::make_buildable(plan.value());
}

std::vector<detail::WallFrame> frames_of(const detail::BuildablePlan& b) {
  return detail::make_wall_frames(b.plan, find_joins(b.plan), b.through_mitre);
}

void BM_WallPairs(benchmark::State& state, const std::string& name, bool in_space) {
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const std::vector<detail::WallFrame> frames = frames_of(buildable(name));
  std::vector<Box2> plan;
  std::vector<SpaceBox> space;
  for (const detail::WallFrame& f : frames) {
    plan.push_back(detail::footprint_box(f));
    space.push_back(detail::footprint_space_box(f));
  }
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = in_space ? find_meeting_boxes(space).size() : find_meeting_boxes(plan).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["walls"] = double(frames.size());
  state.counters["pairs"] = double(pairs);
}

void BM_FindJoins(benchmark::State& state, const std::string& name) {
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const detail::BuildablePlan b = buildable(name);
  for (auto _ : state) benchmark::DoNotOptimize(find_joins(b.plan).pairs.size());
}

void BM_PlanWork(benchmark::State& state, const std::string& name) {
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const detail::BuildablePlan b = buildable(name);
  const Joins joins = find_joins(b.plan);
  const std::vector<detail::WallFrame> frames =
      detail::make_wall_frames(b.plan, joins, b.through_mitre);
  const std::vector<detail::SlabFrame> slabs = detail::make_slab_frames(b.plan, frames);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        detail::plan_work(frames, joins, BooleanPath::automatic, slabs).items.size());
}

void register_all() {
  for (const std::string name : {"arif-putra-pertama-1", "4-BedroomHouse", "Sample", "tower"}) {
    benchmark::RegisterBenchmark(("BM_WallPairs/plan/" + name).c_str(), BM_WallPairs, name, false)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_WallPairs/space/" + name).c_str(), BM_WallPairs, name, true)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_FindJoins/" + name).c_str(), BM_FindJoins, name)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_PlanWork/" + name).c_str(), BM_PlanWork, name)
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace
}  // namespace roomcad

int main(int argc, char** argv) {
  roomcad::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
