// SPDX-License-Identifier: GPL-3.0-or-later
// A thousand plans (or ROOMCAD_STRESS_PLANS: support/stress_plans.h) from the seeded
// generator (testing/random_plan.h), through validation, both build paths and the renderer:
// - verdicts exact: a plan swapped in x and y, or scaled by 1024, gets the same codes on the
//   same objects (both motions are exact on doubles, and verdicts are exact for the numbers
//   as written);
// - the largest part of a plan that validates (walls, openings, lights kept in order while
//   no error appears) builds on the fast path into a closed, manifold, outward solid with the
//   analytic volume; its render (PCF shadows, the plan's lights) has no NaN depth;
// - the same on the CGAL path, with the same volume;
// for every seed on the automatic path, the first 1 in 25 of them on the CGAL path.
#include <algorithm>
#include <cstdio>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "mesh/mesh_check.h"
#include "render/renderer.h"
#include "scene_support.h"
#include "solid/analytic_volume.h"
#include "solid/build_model.h"
#include "solid/wall_check.h"
#include "support/stress_plans.h"
#include "testing/random_plan.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

/// Building is slower than validating: measured on 2 shared cores, a plan's greedy valid part,
/// fast build, checks and render take ~90 ms of CPU; all plans are built (~90 s for the default
/// 1000), since failures are rare (finding S4: 11 seeds in 1000), and the CGAL path (Nef
/// polyhedra, several times slower) on the first 1 in 25 of them (40 of 1000).
std::uint64_t cgal_plan_count(std::uint64_t plans) {
  return std::max<std::uint64_t>(1, plans / 25);
}

samples::RandomPlanOptions plain_options() {
  samples::RandomPlanOptions o;
  o.awkward_numbers = false;  // awkward values are the reader's and validation's robustness tests
  o.awkward_strings = false;
  o.extras = false;
  return o;
}

using Verdict = std::pair<Code, std::vector<std::string>>;

std::multiset<Verdict> verdicts(const Plan& plan) {
  ValidateOptions options;
  options.room_warnings = false;
  std::multiset<Verdict> out;
  for (const Diagnostic& d : validate(plan, options).items) out.insert({d.code, d.objects});
  return out;
}

Plan swapped_xy(Plan p) {
  auto swap = [](Point2& q) { std::swap(q.x, q.y); };
  swap(p.site.origin);
  std::swap(p.site.cells[0], p.site.cells[1]);
  for (Wall& w : p.walls) swap(w.from), swap(w.to);
  return p;
}

Plan scaled(Plan p, double k) {
  p.site.origin = {p.site.origin.x * k, p.site.origin.y * k};
  p.site.cell_size *= k, p.site.max_height *= k, p.site.tolerance *= k;
  for (Wall& w : p.walls) {
    w.from = {w.from.x * k, w.from.y * k}, w.to = {w.to.x * k, w.to.y * k};
    w.thickness *= k, w.height *= k, w.base *= k;
  }
  for (Opening& o : p.openings) o.offset *= k, o.width *= k, o.height *= k, o.sill *= k;
  return p;
}

TEST(RandomPlans, VerdictsAreTheSameUnderExactMotions) {
  const std::uint64_t plans = test::stress_plan_count();
  std::size_t errors = 0;
  for (std::uint64_t seed = 1; seed <= plans; ++seed) {
    SCOPED_TRACE(seed);
    const Plan plan = samples::random_plan(seed, plain_options());
    const auto expected = verdicts(plan);
    errors += expected.size();
    EXPECT_EQ(verdicts(swapped_xy(plan)), expected);
    EXPECT_EQ(verdicts(scaled(plan, 1024.0)), expected);
  }
  EXPECT_GT(errors, plans) << "the generator should make plenty of findings";
}

/// Appends each item of `from` to `to` and keeps it only while the plan validates.
template <class T>
void keep_valid(Plan& plan, std::vector<T> Plan::*member, const std::vector<T>& from) {
  for (const T& item : from) {
    (plan.*member).push_back(item);
    if (!validate(plan, {.room_warnings = false}).ok()) (plan.*member).pop_back();
  }
}

/// The largest part of a random plan that validates, greedily, on a site that holds it: 256 m
/// a side in tiles of 16 m (the site's extent is all validation reads of it; the floor, built
/// and rendered with the walls, is then 256 tiles, not the 65,536 of 1 m tiles that took most
/// of the test's time).
Plan valid_part(const Plan& random) {
  Plan plan = random;
  plan.site.origin = {-128.0, -128.0};
  plan.site.cells = {16, 16};
  plan.site.cell_size = 16.0;
  plan.site.max_height = 16.0;
  plan.walls.clear(), plan.openings.clear(), plan.lights.clear(), plan.cameras.clear();
  keep_valid(plan, &Plan::walls, random.walls);
  keep_valid(plan, &Plan::openings, random.openings);
  keep_valid(plan, &Plan::lights, random.lights);
  return plan;
}

/// Builds the walls on one path; expects a valid solid with the analytic volume.
/// @param[in,out] total  the build's wall counts are added to it
/// @return the volume.
double expect_valid_build(const Plan& plan, BooleanPath path, BuildStats& total) {
  BuildOptions options;
  options.boolean = path;
  Model model;
  BuildStats stats;
  EXPECT_NO_THROW(model = build_model(plan, options, &stats));
  total.fast_path_walls += stats.fast_path_walls;
  total.general_path_walls += stats.general_path_walls;
  total.nef_path_walls += stats.nef_path_walls;
  const SolidCheck c = check_solid(model.walls);
  const char* name = path == BooleanPath::nef ? "nef" : "auto";
  EXPECT_TRUE(c.is_valid()) << name << ": " << c.border_edges << " border edges, "
                            << c.non_manifold_vertices << " non-manifold vertices, "
                            << c.self_intersections << " self-intersections, "
                            << c.degenerate_triangles << " degenerate";
  const double analytic = analytic_wall_volume(plan);
  EXPECT_NEAR(c.volume, analytic, volume_tolerance(model.walls, analytic)) << name;
  if (path == BooleanPath::automatic) {
    FrameBuffers frame;
    render_model(
        model,
        RenderOptions{.width = 64, .height = 48, .shadow_resolution = 256, .lights = plan.lights},
        frame);
    EXPECT_EQ(test::count_bad_depths(frame.depth), 0);
  }
  return c.volume;
}

TEST(RandomPlans, ValidPartsBuildClosedWithTheirVolumeOnBothPaths) {
  const std::uint64_t plans = test::stress_plan_count();
  const std::uint64_t cgal_plans = cgal_plan_count(plans);
  BuildStats fast, cgal;
  std::size_t openings = 0;
  for (std::uint64_t seed = 1; seed <= plans; ++seed) {
    SCOPED_TRACE(seed);
    const Plan plan = valid_part(samples::random_plan(seed, plain_options()));
    openings += plan.openings.size();
    const double volume = expect_valid_build(plan, BooleanPath::automatic, fast);
    if (seed > cgal_plans) continue;
    const double exact = expect_valid_build(plan, BooleanPath::nef, cgal);
    EXPECT_NEAR(volume, exact, 2e-9 * exact);
  }
  // Not vacuous: many walls, both paths of the automatic build, openings cut.
  EXPECT_GT(fast.fast_path_walls + fast.general_path_walls, 2 * plans);
  EXPECT_GT(fast.fast_path_walls, plans / 3);
  EXPECT_GT(fast.general_path_walls, plans);
  EXPECT_EQ(fast.nef_path_walls, 0u);
  EXPECT_GT(openings, plans / 2);
  std::printf(
      "random plans: %llu (%llu on the Nef path): %zu walls on the fast path, %zu "
      "on the general path, %zu openings; Nef path: %zu walls\n",
      static_cast<unsigned long long>(plans), static_cast<unsigned long long>(cgal_plans),
      fast.fast_path_walls, fast.general_path_walls, openings, cgal.nef_path_walls);
}

}  // namespace
}  // namespace roomcad
