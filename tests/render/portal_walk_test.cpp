// SPDX-License-Identifier: GPL-3.0-or-later
// The portal walk draws exactly the picture back-face culling draws: every bundled plan, from
// inside each of its cells, looking four ways, byte for byte.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "render/portal_walk.h"
#include "render/renderer.h"
#include "solid/build_model.h"
#include "support/plan_reading.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

std::vector<std::filesystem::path> bundled_plans() {
  std::vector<std::filesystem::path> plans;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(test::source_dir() / "examples")) {
    if (entry.path().extension() != ".json") continue;
    if (test::read_bytes(entry.path()).find("\"roomcad-plan\"") == std::string::npos) continue;
    plans.push_back(entry.path());
  }
  std::sort(plans.begin(), plans.end());
  return plans;
}

Camera looking(const Vec3& eye, double yaw_deg) {
  const double a = yaw_deg * M_PI / 180.0;
  Camera c;
  c.eye = eye;
  c.target = {eye.x + std::cos(a), eye.y + std::sin(a), eye.z - 0.2};
  c.fov_deg = 70.0;
  return c;
}

/// A point of the cell at eye height (1.6 m over its floor, kept within the heights an eye may
/// take) from which a walk starts, or nullopt: tries the box's centre, then a 9 x 9 grid.
std::optional<Vec3> eye_in(const Scene& scene, const Cell& cell, double aspect) {
  const double low = cell.eye_low + 0.2, high = std::min(cell.eye_high, cell.top_z) - 0.2;
  if (low >= high) return std::nullopt;
  const double z = std::clamp(cell.floor_z + 1.6, low, high);
  const Box3& b = cell.bounds;
  std::vector<Vec3> tries{{(b.low[0] + b.high[0]) / 2, (b.low[1] + b.high[1]) / 2, z}};
  for (int i = 1; i < 10; ++i)
    for (int j = 1; j < 10; ++j)
      tries.push_back({b.low[0] + (b.high[0] - b.low[0]) * i / 10.0,
                       b.low[1] + (b.high[1] - b.low[1]) * j / 10.0, z});
  for (const Vec3& eye : tries) {
    const CameraMatrices cam =
        rebase_camera(make_camera_matrices(looking(eye, 0.0), scene.bounds, aspect), scene.origin);
    if (walk_portals(scene, cam)) return eye;
  }
  return std::nullopt;
}

TEST(PortalWalk, EveryBundledPlanLooksTheSameFromInsideEachCell) {
  const auto plans = bundled_plans();
  ASSERT_GT(plans.size(), 10u);
  std::size_t cells = 0, views = 0, back_triangles = 0, portal_triangles = 0;
  for (const auto& path : plans) {
    const test::PlanReading read = test::read_plan_at(path);
    ASSERT_TRUE(read.plan) << path;
    const Model model = build_model(*read.plan, BuildOptions{.cells = true});
    const Scene scene = flatten_model(model);
    if (!scene.cells) continue;  // no wall closes a room: nothing to walk
    cells += scene.cells->cells.cells.size();
    for (const Cell& cell : scene.cells->cells.cells) {
      const auto eye = eye_in(scene, cell, 16.0 / 9.0);
      if (!eye) continue;
      for (double yaw : {0.0, 90.0, 180.0, 270.0}) {
        RenderOptions options{.width = 256,
                              .height = 144,
                              .camera = looking(*eye, yaw + 20.0),
                              .shadows = ShadowFilter::off,
                              .threads = 2};
        FrameBuffers back, portals;
        RenderStats back_stats, stats;
        options.cull = FaceCull::back_faces;
        render_scene(scene, options, back, &back_stats);
        options.cull = FaceCull::portals;
        render_scene(scene, options, portals, &stats);
        ++views;
        back_triangles += back_stats.screen_triangles;
        portal_triangles += stats.screen_triangles;
        ASSERT_EQ(back.color.pixels, portals.color.pixels)
            << path << " eye " << eye->x << "," << eye->y << "," << eye->z << " yaw " << yaw;
        ASSERT_EQ(back.objects.ids, portals.objects.ids) << path;
      }
    }
  }
  // the walk started in most cells, and skipped triangles back-face culling keeps
  EXPECT_GT(cells, plans.size());
  EXPECT_GT(views, cells * 2);
  EXPECT_LT(portal_triangles, back_triangles * 0.95);
  std::printf("%zu plans, %zu cells, %zu views: %zu triangles on screen, %zu with back faces\n",
              plans.size(), cells, views, portal_triangles, back_triangles);
}

}  // namespace
}  // namespace roomcad
