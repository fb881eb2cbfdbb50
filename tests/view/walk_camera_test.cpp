// SPDX-License-Identifier: GPL-3.0-or-later
// Walking in the first person: standing at eye height, stepping level, turning about the eye.
#include <gtest/gtest.h>

#include <cmath>

#include "view/walk_camera.h"

namespace roomcad {
namespace {

Camera looking_down_at(Vec3 target) {
  Camera c;
  c.eye = {target.x - 3.0, target.y - 4.0, 10.0};
  c.target = target;
  c.projection = Projection::orthographic;
  return c;
}

TEST(WalkCamera, StandsWhereTheViewLookedAtEyeHeightLookingLevel) {
  const Camera c = stand_at_target(looking_down_at({2.0, 3.0, 0.0}), 3.0);
  EXPECT_EQ(c.projection, Projection::perspective);
  EXPECT_DOUBLE_EQ(c.eye.x, 2.0);
  EXPECT_DOUBLE_EQ(c.eye.y, 3.0);
  EXPECT_DOUBLE_EQ(c.eye.z, 3.0 + kWalkEyeHeight);
  EXPECT_DOUBLE_EQ(c.target.z, c.eye.z);
  EXPECT_NEAR(c.target.x - c.eye.x, 0.6, 1e-12);  // the view's direction, level: (3, 4) / 5
  EXPECT_NEAR(c.target.y - c.eye.y, 0.8, 1e-12);
  Camera straight_down;
  straight_down.eye = {1.0, 1.0, 9.0};
  straight_down.target = {1.0, 1.0, 0.0};
  const Camera north = stand_at_target(straight_down, 0.0);
  EXPECT_DOUBLE_EQ(north.target.y - north.eye.y, 1.0);
}

TEST(WalkCamera, StepsKeepTheHeightAndTurnsKeepTheEye) {
  Camera c = stand_at_target(looking_down_at({0.0, 0.0, 0.0}), 0.0);
  c = look_around(c, 0.0, -30.0);  // looking down a little: a step is still level
  const Camera stepped = walk_forward(c, 2.0);
  EXPECT_DOUBLE_EQ(stepped.eye.z, c.eye.z);
  EXPECT_NEAR(std::hypot(stepped.eye.x - c.eye.x, stepped.eye.y - c.eye.y), 2.0, 1e-12);
  const Camera back = walk_forward(stepped, -2.0);
  EXPECT_NEAR(back.eye.x, c.eye.x, 1e-12);
  EXPECT_NEAR(back.eye.y, c.eye.y, 1e-12);
  Camera turned = c;
  for (int i = 0; i < 4; ++i) turned = look_around(turned, 90.0, 0.0);
  EXPECT_EQ(turned.eye, c.eye);
  EXPECT_NEAR(turned.target.x, c.target.x, 1e-9);
  EXPECT_NEAR(turned.target.y, c.target.y, 1e-9);
  EXPECT_NEAR(turned.target.z, c.target.z, 1e-9);
  const Camera up = look_around(c, 0.0, 500.0);  // stops short of straight up
  EXPECT_LT(up.target.z - up.eye.z, 1.0);
  EXPECT_GT(up.target.z - up.eye.z, 0.99);
}

}  // namespace
}  // namespace roomcad
