// SPDX-License-Identifier: GPL-3.0-or-later
// Shadows against ray-traced shadows: hard shadows agree on every floor pixel more than one
// shadow-map texel from a shadow edge; unlit shadowed pixels are the colour times ambient.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "render/renderer.h"
#include "scene_support.h"

namespace roomcad {
namespace {

using test::RayCaster;

Model make_courtyard() {
  Model m;
  m.objects = {"floor", "w1", "w2", "post"};
  test::add_floor(m.floor, {-6.0, -6.0}, {14.0, 14.0}, 0);
  test::add_box(m.walls, {0.0, 0.0, 0.0}, {6.0, 0.3, 2.8}, 1);
  test::add_box(m.walls, {0.0, 0.3, 0.0}, {0.3, 5.0, 2.0}, 2);
  test::add_box(m.walls, {4.0, 6.0, 0.0}, {4.5, 6.5, 3.5}, 3);
  return m;
}

struct ShadowCase {
  Model model = make_courtyard();
  Light light = default_light();  // the spec's sun
  RenderOptions options;
};

ShadowCase make_case(ShadowFilter filter) {
  ShadowCase c;
  c.options = RenderOptions{.width = 200,
                            .height = 200,
                            .shading = ShadingMode::unlit,
                            .shadows = filter,
                            .shadow_resolution = 512,
                            .lights = {c.light}};
  c.options.camera =
      test::look_from({4.0, 4.0, 30.0}, {4.0, 4.0, 0.0}, 50.0, 20.0, {0.0, 1.0, 0.0});
  return c;
}

/// Whether the reference shadow changes within `radius` metres of floor point `p`, measured
/// across the light (in the shadow map's plane), or the point is that close to where a wall
/// stands on the floor (a contact line is an edge of the occluder in the map too).
bool is_near_shadow_edge(const RayCaster& occluders, const RayCaster& all, const glm::dvec3& p,
                         const glm::dvec3& to_light, double radius, bool shadowed) {
  const glm::dvec3 across = glm::normalize(glm::cross(to_light, glm::dvec3(0, 0, 1)));
  const glm::dvec3 up = glm::cross(across, to_light);
  for (const double r : {0.5 * radius, radius}) {
    for (int k = 0; k < 16; ++k) {
      const double a = k * std::numbers::pi / 8.0;
      glm::dvec3 q = p + r * (std::cos(a) * across + std::sin(a) * up);
      q -= to_light * (q.z / to_light.z);  // back onto the floor along the light
      if (occluders.is_blocked(q, to_light) != shadowed) return true;
      if (all.first_object(q + glm::dvec3(0, 0, 50), {0, 0, -1}) != 0) return true;
    }
  }
  return false;
}

TEST(Render, HardShadowsAgreeWithRayTracedShadowsAwayFromEdges) {
  const ShadowCase c = make_case(ShadowFilter::hard);
  FrameBuffers out;
  render_model(c.model, c.options, out);
  const Scene scene = flatten_model(c.model);
  const double texel = render_shadow_map(scene, c.light, c.options.shadow_resolution).texel_size();
  const CameraMatrices cam = frame_camera(scene, c.options);
  const RayCaster occluders({&c.model.walls});
  const RayCaster all({&c.model.walls, &c.model.floor});
  const glm::dvec3 to_light = -glm::normalize(glm::dvec3(-0.4, 0.5, -1.0));
  int compared = 0, shadowed_count = 0;
  for (int y = 0; y < c.options.height; ++y)
    for (int x = 0; x < c.options.width; ++x) {
      const test::PixelRay r = test::pixel_ray(cam, c.options.width, c.options.height, x, y);
      if (all.first_object(r.origin, r.direction) != 0) continue;  // floor pixels only
      const glm::dvec3 p = r.origin + r.direction * (-r.origin.z / r.direction.z);
      const bool shadowed = occluders.is_blocked(p, to_light);
      if (is_near_shadow_edge(occluders, all, p, to_light, texel, shadowed)) continue;
      ++compared;
      shadowed_count += shadowed;
      const std::uint8_t* px = out.color.at(x, y);
      const double factor = shadowed ? c.light.ambient : 1.0;
      EXPECT_NEAR(px[0], test::kFloorColor.r * factor, 1.0) << x << "," << y;
      EXPECT_NEAR(px[1], test::kFloorColor.g * factor, 1.0) << x << "," << y;
    }
  EXPECT_GT(compared, 200 * 200 / 2);
  EXPECT_GT(shadowed_count, 1000);  // the test sees real shadows, not only lit floor
}

TEST(Render, PcfMatchesHardShadowsAwayFromEdgesAndSoftensThem) {
  FrameBuffers hard, pcf;
  const ShadowCase h = make_case(ShadowFilter::hard), p = make_case(ShadowFilter::pcf);
  render_model(h.model, h.options, hard);
  render_model(p.model, p.options, pcf);
  int differ = 0, in_between = 0;
  const int lit = test::kFloorColor.r, dark = static_cast<int>(std::lround(lit * 0.25));
  for (std::size_t i = 0; i < hard.color.pixels.size(); i += 3) {
    if (hard.objects.ids[i / 3] != 0) continue;
    const int a = hard.color.pixels[i], b = pcf.color.pixels[i];
    differ += a != b;
    in_between += b > dark + 1 && b < lit - 1;
  }
  EXPECT_GT(in_between, 20);          // penumbra pixels exist
  EXPECT_LT(differ, 200 * 200 / 10);  // only near edges
}

}  // namespace
}  // namespace roomcad
