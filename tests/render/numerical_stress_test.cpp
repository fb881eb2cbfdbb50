// SPDX-License-Identifier: GPL-3.0-or-later
// Numerical stress for the renderer: a wall turned by 1e-9, 45 and 89.9999999 degrees, at the
// origin and 1e6 and 1e7 m from it, lit by a high and a grazing sun: its sunlit face shows no
// shadowed pixel (no acne) with hard or PCF shadows at 1024 and 4096 texels; and rooms at
// those places whose frames have no NaN, infinite or negative depth.
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "scene_support.h"
#include "solid/build_model.h"
#include "testing/plan_builders.h"

namespace roomcad {
namespace {

/// Where the wall is: its from end, its direction in degrees.
struct Placement {
  double degrees;
  glm::dvec2 from;
};

/// @param distances  how far from the origin, along (1, -1)
std::vector<Placement> placements(std::initializer_list<double> distances) {
  std::vector<Placement> out;
  for (const double d : distances)
    for (const double degrees : {1e-9, 45.0, 89.9999999}) out.push_back({degrees, {d, -d}});
  return out;
}

/// A plain wall 6 m long, 0.2 m thick, 2.5 m high, on a site that holds it.
Plan wall_plan(const Placement& p) {
  const double a = p.degrees * std::numbers::pi / 180.0;
  Plan plan;
  plan.walls.push_back(
      samples::make_wall("w", {p.from.x, p.from.y},
                         {p.from.x + 6.0 * std::cos(a), p.from.y + 6.0 * std::sin(a)}, 0.2));
  plan.site.origin = {p.from.x - 10.0, p.from.y - 10.0};
  plan.site.cells = {20, 20};
  return plan;
}

/// The sun on the wall's right-hand face (seen walking from -> to): `facing` is the cosine
/// share towards that face's normal, the rest along the wall and up.
Light sun_on_right_face(const Placement& p, double facing) {
  const double a = p.degrees * std::numbers::pi / 180.0;
  const glm::dvec3 along(std::cos(a), std::sin(a), 0.0), normal(std::sin(a), -std::cos(a), 0.0);
  const glm::dvec3 to_sun = glm::normalize(facing * normal + 0.3 * along + glm::dvec3(0, 0, 1));
  Light sun = default_light();
  sun.direction = {-to_sun.x, -to_sun.y, -to_sun.z};
  return sun;
}

/// Unlit frame of the wall's right-hand face, seen square on from 20 m (orthographic).
RenderOptions face_view(const Placement& p, const Light& sun, ShadowFilter shadows,
                        int resolution) {
  const double a = p.degrees * std::numbers::pi / 180.0;
  const glm::dvec3 along(std::cos(a), std::sin(a), 0.0), normal(std::sin(a), -std::cos(a), 0.0);
  const glm::dvec3 centre = glm::dvec3(p.from, 1.25) + 3.0 * along;
  RenderOptions o{.width = 96,
                  .height = 96,
                  .shading = ShadingMode::unlit,
                  .shadows = shadows,
                  .shadow_resolution = resolution,
                  .lights = {sun},
                  .parts = {true, false, false}};
  o.camera = test::look_from(centre + 20.0 * normal, centre, 50.0, 3.0);
  return o;
}

TEST(NumericalStress, SunlitWallFaceHasNoAcneTurned) {
  for (const Placement& p : placements({0.0, 1e6, 1e7})) {
    const Model model = build_model(wall_plan(p));
    for (const double facing : {0.6, 0.15}) {  // n.l about 0.5 and 0.14 (82 degrees)
      const Light sun = sun_on_right_face(p, facing);
      FrameBuffers unshadowed;
      render_model(model, face_view(p, sun, ShadowFilter::off, 1024), unshadowed);
      for (const ShadowFilter filter : {ShadowFilter::hard, ShadowFilter::pcf})
        for (const int resolution : {1024, 4096}) {
          SCOPED_TRACE(fmt::format("{} deg at ({}, {}), facing {}, {} shadows, {} texels",
                                   p.degrees, p.from.x, p.from.y, facing,
                                   filter == ShadowFilter::hard ? "hard" : "pcf", resolution));
          FrameBuffers frame;
          render_model(model, face_view(p, sun, filter, resolution), frame);
          EXPECT_EQ(test::count_bad_depths(frame.depth), 0);
          int wall = 0, shadowed = 0;
          for (std::size_t i = 0; i < frame.objects.ids.size(); ++i) {
            if (frame.objects.ids[i] < 0) continue;
            ++wall;
            for (int c = 0; c < 3; ++c)
              shadowed += frame.color.pixels[3 * i + c] != unshadowed.color.pixels[3 * i + c];
          }
          EXPECT_GT(wall, 96 * 96 * 3 / 4) << "the face fills most of the frame";
          EXPECT_EQ(shadowed, 0) << "acne: sunlit pixels darkened";
        }
    }
  }
}

TEST(NumericalStress, RoomFarAwayAndTurnedHasNoBadDepth) {
  for (const Placement& p : placements({0.0, 1e6, 1e7})) {
    SCOPED_TRACE(fmt::format("{} deg at ({}, {})", p.degrees, p.from.x, p.from.y));
    Plan plan = wall_plan(p);
    const Point2 corner = plan.walls[0].to;
    plan.walls.push_back(samples::make_wall("back", corner, {corner.x - 1, corner.y + 4}, 0.2));
    FrameBuffers frame;
    RenderStats stats;
    render_model(build_model(plan), RenderOptions{.width = 128, .height = 96}, frame, &stats);
    EXPECT_EQ(test::count_bad_depths(frame.depth), 0);
    EXPECT_GT(stats.screen_triangles, 0u);
  }
}

}  // namespace
}  // namespace roomcad
