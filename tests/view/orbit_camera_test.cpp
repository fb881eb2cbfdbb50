// SPDX-License-Identifier: GPL-3.0-or-later
// Camera moves: turns keep the distance and come back after a full turn, pans move eye and
// target together, zoom and projection toggles keep what is seen at the target.
#include <gtest/gtest.h>

#include <cmath>

#include "view/orbit_camera.h"

namespace roomcad {
namespace {

Camera sample() {
  Camera c;
  c.eye = {10, -8, 6};
  c.target = {2, 3, 1};
  return c;
}

double distance(const Camera& c) {
  return std::hypot(c.eye.x - c.target.x, c.eye.y - c.target.y, c.eye.z - c.target.z);
}

void expect_near(const Vec3& a, const Vec3& b, double tol = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(OrbitCamera, FourQuarterTurnsAboutEachAxisComeBack) {
  for (const glm::dvec3 axis : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)}) {
    Camera c = sample();
    for (int i = 0; i < 4; ++i) {
      c = rotate_camera(c, axis, 90.0);
      EXPECT_NEAR(distance(c), distance(sample()), 1e-9);
      expect_near(c.target, sample().target, 0.0);
    }
    expect_near(c.eye, sample().eye);
    expect_near(c.up, sample().up);
  }
  const Camera turned = rotate_camera(sample(), {0, 0, 1}, 90.0);  // eye offset (8,-11) -> (11, 8)
  expect_near(turned.eye, Vec3{2 + 11, 3 + 8, 6});
  EXPECT_EQ(rotate_camera(sample(), {0, 0, 0}, 30.0), sample());
}

TEST(OrbitCamera, OrbitUpRaisesTheEye) {
  const Camera up = orbit_camera(sample(), 0.0, 15.0);
  EXPECT_GT(up.eye.z, sample().eye.z);
  EXPECT_NEAR(distance(up), distance(sample()), 1e-9);
  const Camera left = orbit_camera(sample(), 15.0, 0.0);
  EXPECT_NEAR(left.eye.z, sample().eye.z, 1e-12);
}

TEST(OrbitCamera, PanMovesEyeAndTargetTogether) {
  const Camera c = pan_camera(sample(), 0.1, 0.05);
  const Vec3 de{c.eye.x - sample().eye.x, c.eye.y - sample().eye.y, c.eye.z - sample().eye.z};
  const Vec3 dt{c.target.x - sample().target.x, c.target.y - sample().target.y,
                c.target.z - sample().target.z};
  expect_near(de, dt);
  EXPECT_NEAR(std::hypot(de.x, de.y, de.z), std::hypot(0.1, 0.05) * visible_height(sample()), 1e-9);
}

TEST(OrbitCamera, ZoomAndProjectionToggleKeepWhatIsSeen) {
  EXPECT_NEAR(distance(zoom_camera(sample(), 0.5)), distance(sample()) * 0.5, 1e-9);
  EXPECT_NEAR(distance(zoom_camera(sample(), 1e-9)), 0.1, 1e-9);  // never onto the target
  const Camera parallel = toggle_projection(sample());
  EXPECT_EQ(parallel.projection, Projection::orthographic);
  EXPECT_NEAR(parallel.view_height, visible_height(sample()), 1e-9);
  EXPECT_NEAR(zoom_camera(parallel, 0.5).view_height, parallel.view_height * 0.5, 1e-9);
  const Camera back = toggle_projection(parallel);
  EXPECT_EQ(back.projection, Projection::perspective);
  expect_near(back.eye, sample().eye, 1e-9);
}

}  // namespace
}  // namespace roomcad
