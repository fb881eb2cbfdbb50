// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/floating_horizon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "render/surface_expression.h"

namespace roomcad {
namespace {

SurfaceFunction function_of(const std::string& text) {
  Result<SurfaceExpression> parsed = parse_surface_expression(text);
  EXPECT_TRUE(parsed.ok()) << text;
  SurfaceExpression expression = parsed ? std::move(parsed).value() : SurfaceExpression{};
  return [expression](double x, double z) { return expression.evaluate(x, z); };
}

/// The picture-plane point of a surface point, mapped to the screen as the drawing says.
ScreenPoint expected_screen(const SurfaceDrawing& d, double x, double y, double z, double rx_deg) {
  const double rx = rx_deg * std::numbers::pi / 180.0;  // no rotation about y in these tests
  const double picture_y = y * std::cos(rx) + z * std::sin(rx);
  return {d.origin_x + d.scale_x * x, d.origin_y - d.scale_y * picture_y};
}

SurfaceScreen plain_screen() {
  return {.width = 800, .height = 600, .margin = 10, .columns = 800, .side_edges = false};
}

TEST(FloatingHorizon, TiltedPlaneShowsEverySectionWhole) {
  // y = 0 seen from 30 degrees above: section z = c is the horizontal line Y = c sin 30, each
  // higher than all before it, so each lies wholly above the upper horizon.
  const SurfaceView view{
      .x_min = -2, .x_max = 2, .z_min = -1, .z_max = 1, .dx = 0.5, .dz = 0.25, .rotate_x_deg = 30};
  const SurfaceDrawing d = draw_floating_horizon(function_of("0"), view, plain_screen());
  ASSERT_EQ(d.polylines.size(), 9u);
  for (std::size_t j = 0; j < 9; ++j) {
    const HorizonPolyline& line = d.polylines[j];
    EXPECT_EQ(line.side, j == 0 ? HorizonSide::first : HorizonSide::upper);
    ASSERT_EQ(line.points.size(), 9u) << "section " << j;  // every sample, nothing else
    const double z = -1.0 + 0.25 * j;
    for (std::size_t i = 0; i < 9; ++i) {
      const ScreenPoint want = expected_screen(d, -2.0 + 0.5 * i, 0.0, z, 30);
      EXPECT_NEAR(line.points[i].x, want.x, 1e-9);
      EXPECT_NEAR(line.points[i].y, want.y, 1e-9);
    }
  }
  // The window fits the picture: the plane spans the full width inside the margins.
  EXPECT_NEAR(d.polylines[0].points.front().x, 10.0, 1e-9);
  EXPECT_NEAR(d.polylines[0].points.back().x, 790.0, 1e-9);
}

TEST(FloatingHorizon, PlaneTurnedAboutBothAxesShowsEverySection) {
  // y = 0 turned 30 degrees about y, then 30 about x: section z = c is the line
  // X = x cos ry + c sin ry, Y = (c cos ry - x sin ry) sin rx. All sections are parallel and
  // each lies dz sin rx / cos ry above the one before at equal X, so all are wholly visible.
  const double ry = 30 * std::numbers::pi / 180, rx = 30 * std::numbers::pi / 180;
  const SurfaceView view{.x_min = -2,
                         .x_max = 2,
                         .z_min = -1,
                         .z_max = 1,
                         .dx = 0.5,
                         .dz = 0.25,
                         .rotate_x_deg = 30,
                         .rotate_y_deg = 30};
  const SurfaceDrawing d = draw_floating_horizon(function_of("0"), view, plain_screen());
  ASSERT_EQ(d.polylines.size(), 9u);
  for (std::size_t j = 0; j < 9; ++j) {
    const double c = -1.0 + 0.25 * j;
    ASSERT_EQ(d.polylines[j].points.size(), 9u) << "section " << j;
    for (std::size_t i = 0; i < 9; ++i) {
      const double x = -2.0 + 0.5 * i;
      const double px = x * std::cos(ry) + c * std::sin(ry);
      const double py = (c * std::cos(ry) - x * std::sin(ry)) * std::sin(rx);
      EXPECT_NEAR(d.polylines[j].points[i].x, d.origin_x + d.scale_x * px, 1e-9);
      EXPECT_NEAR(d.polylines[j].points[i].y, d.origin_y - d.scale_y * py, 1e-9);
    }
  }
}

TEST(FloatingHorizon, SideEdgesJoinTheSectionsOfAPlane) {
  const SurfaceView view{
      .x_min = -2, .x_max = 2, .z_min = -1, .z_max = 1, .dx = 0.5, .dz = 0.5, .rotate_x_deg = 30};
  SurfaceScreen screen = plain_screen();
  screen.side_edges = true;
  const SurfaceDrawing d = draw_floating_horizon(function_of("0"), view, screen);
  // The first section, then each later one drawn as left edge + section + right edge.
  ASSERT_EQ(d.polylines.size(), 5u);
  for (std::size_t j = 1; j < 5; ++j) {
    const auto& points = d.polylines[j].points;
    ASSERT_EQ(points.size(), 9u + 2u);
    EXPECT_NEAR(points.front().x, points[1].x, 1e-9);  // vertical edge at x = x_min
    EXPECT_GT(points.front().y, points[1].y);          // rising from the section in front
    EXPECT_NEAR(points.back().x, points[points.size() - 2].x, 1e-9);
  }
}

/// g(c): the height of section z = c of the saddle y = x^2 - z^2 at x = 0, seen from rx above.
double saddle_offset(double c, double rx_deg) {
  const double rx = rx_deg * std::numbers::pi / 180.0;
  return c * std::sin(rx) - c * c * std::cos(rx);
}

TEST(FloatingHorizon, SaddleMatchesAnalyticHorizons) {
  // Section z = c of the saddle, rotated by rx about x, is Y = x^2 cos rx + g(c): all sections
  // are the same parabola shifted by g(c). So the upper horizon after sections c_0..c_k is the
  // parabola shifted by max g, the lower one by min g, and a section is visible exactly when
  // g(c) exceeds every earlier g (or falls below every earlier one). g rises up to c = tan(rx)/2
  // = 0.5 for rx = 45 degrees and then falls, but never below g(-2): so sections -2..0.5 are
  // visible whole, above the upper horizon, and all later ones are hidden.
  const double rx = 45;
  const SurfaceView view{
      .x_min = -2, .x_max = 2, .z_min = -2, .z_max = 2, .dx = 0.25, .dz = 0.25, .rotate_x_deg = rx};
  const SurfaceDrawing d = draw_floating_horizon(function_of("x*x - z*z"), view, plain_screen());
  double highest = -INFINITY;
  std::size_t visible = 0;
  for (int j = 0; j <= 16; ++j) {
    const double c = -2.0 + 0.25 * j;
    if (saddle_offset(c, rx) <= highest) continue;
    highest = saddle_offset(c, rx);
    ASSERT_LT(visible, d.polylines.size());
    const HorizonPolyline& line = d.polylines[visible++];
    EXPECT_EQ(line.side, j == 0 ? HorizonSide::first : HorizonSide::upper);
    ASSERT_EQ(line.points.size(), 17u) << "section z = " << c;
    for (std::size_t i = 0; i < 17; ++i) {
      const double x = -2.0 + 0.25 * i;
      const ScreenPoint want = expected_screen(d, x, x * x - c * c, c, rx);
      EXPECT_NEAR(line.points[i].x, want.x, 1e-9);
      EXPECT_NEAR(line.points[i].y, want.y, 1e-9);
    }
  }
  EXPECT_EQ(visible, 11u);  // z = -2, -1.75, ..., 0.5
  EXPECT_EQ(d.polylines.size(), visible);
}

TEST(FloatingHorizon, PartlyHiddenSectionIsCutAtTheHorizons) {
  // Three sections (z = 0, 1, 2, seen straight on): Y = -1, Y = 1, then Y = x + 0.3. The third
  // is visible below the lower horizon Y = -1 for x < -1.3 and above the upper one Y = 1 for
  // x > 0.7; the cut points are the linear intersections, away from any sample.
  const std::string f = "-(z-1)*(z-2)/2 - z*(z-2) + (x+0.3)*z*(z-1)/2";
  const SurfaceView view{.x_min = -2, .x_max = 2, .z_min = 0, .z_max = 2, .dx = 0.5, .dz = 1};
  const SurfaceDrawing d = draw_floating_horizon(function_of(f), view, plain_screen());
  ASSERT_EQ(d.polylines.size(), 4u);
  const auto world_x = [&](const ScreenPoint& p) { return (p.x - d.origin_x) / d.scale_x; };
  const auto world_y = [&](const ScreenPoint& p) { return (d.origin_y - p.y) / d.scale_y; };
  const HorizonPolyline& low = d.polylines[2];
  EXPECT_EQ(low.side, HorizonSide::lower);
  ASSERT_EQ(low.points.size(), 3u);  // x = -2, -1.5 and the cut at -1.3
  EXPECT_NEAR(world_x(low.points.front()), -2.0, 1e-9);
  EXPECT_NEAR(world_x(low.points.back()), -1.3, 1e-9);
  EXPECT_NEAR(world_y(low.points.back()), -1.0, 1e-9);
  const HorizonPolyline& high = d.polylines[3];
  EXPECT_EQ(high.side, HorizonSide::upper);
  ASSERT_EQ(high.points.size(), 4u);  // the cut at 0.7, then x = 1, 1.5, 2
  EXPECT_NEAR(world_x(high.points.front()), 0.7, 1e-9);
  EXPECT_NEAR(world_y(high.points.front()), 1.0, 1e-9);
  EXPECT_NEAR(world_x(high.points.back()), 2.0, 1e-9);
}

TEST(FloatingHorizon, MissingSamplesAreGaps) {
  const SurfaceView view{.x_min = -1, .x_max = 1, .z_min = 0, .z_max = 0, .dx = 0.5, .dz = 1};
  // ln |x| is undefined at x = 0 only: the single section falls into two polylines.
  const SurfaceDrawing split =
      draw_floating_horizon(function_of("ln(abs(x))"), view, plain_screen());
  ASSERT_EQ(split.polylines.size(), 2u);
  EXPECT_EQ(split.polylines[0].points.size(), 2u);
  EXPECT_EQ(split.polylines[1].points.size(), 2u);
  // sqrt(x) exists for x >= 0 only: one polyline over the right half.
  const SurfaceDrawing half = draw_floating_horizon(function_of("sqrt(x)"), view, plain_screen());
  ASSERT_EQ(half.polylines.size(), 1u);
  for (const ScreenPoint& p : half.polylines[0].points) EXPECT_GE(p.x, half.origin_x - 1e-9);
  // Nothing defined at all: an empty drawing, not a crash.
  EXPECT_TRUE(
      draw_floating_horizon(function_of("sqrt(-1)"), view, plain_screen()).polylines.empty());
}

TEST(FloatingHorizon, IsDeterministic) {
  const SurfaceView view{.x_min = -2,
                         .x_max = 2,
                         .z_min = -2,
                         .z_max = 2,
                         .dx = 0.05,
                         .dz = 0.1,
                         .rotate_x_deg = 30,
                         .rotate_y_deg = 10};
  const SurfaceFunction f = function_of("x*z*(x+z)*(x-z)");
  const SurfaceDrawing a = draw_floating_horizon(f, view, SurfaceScreen{});
  const SurfaceDrawing b = draw_floating_horizon(f, view, SurfaceScreen{});
  ASSERT_EQ(a.polylines.size(), b.polylines.size());
  ASSERT_FALSE(a.polylines.empty());
  for (std::size_t k = 0; k < a.polylines.size(); ++k) {
    EXPECT_EQ(a.polylines[k].points, b.polylines[k].points);
  }
}

TEST(FloatingHorizon, WindowStretchesOrKeepsTheAspect) {
  // The front section of y = 4x seen straight on is the line from (-1, -4) to (1, 4).
  const SurfaceView view{.x_min = -1, .x_max = 1, .z_min = 0, .z_max = 0, .dx = 1, .dz = 1};
  SurfaceScreen screen = plain_screen();
  const SurfaceDrawing stretched = draw_floating_horizon(function_of("4*x"), view, screen);
  ASSERT_EQ(stretched.polylines.size(), 1u);
  const auto& line = stretched.polylines[0].points;
  EXPECT_EQ(line.front(), (ScreenPoint{10, 590}));  // corner to corner inside the margins
  EXPECT_EQ(line.back(), (ScreenPoint{790, 10}));
  screen.keep_aspect = true;
  const SurfaceDrawing kept = draw_floating_horizon(function_of("4*x"), view, screen);
  EXPECT_DOUBLE_EQ(kept.scale_x, kept.scale_y);
  EXPECT_DOUBLE_EQ(kept.scale_y, 580.0 / 8.0);  // the height limits the scale
  EXPECT_NEAR(kept.polylines[0].points.front().x, 400 - 72.5, 1e-9);
}

TEST(FloatingHorizon, RejectsBadRequests) {
  // Each bad field is a usage_error whose message names the field and its value.
  auto problem = [](const SurfaceView& view) {
    const Status status = check_surface_request(view, SurfaceScreen{});
    EXPECT_EQ(status.code(), Code::usage_error);
    return status ? std::string() : status.message();
  };
  SurfaceView view;
  view.dx = -1;
  EXPECT_EQ(problem(view), "dx must be positive, got -1");
  view = SurfaceView{};
  view.rotate_x_deg = 90;
  EXPECT_NE(problem(view).find("rotate_x"), std::string::npos);
  view = SurfaceView{};
  view.dx = 1e-9;  // billions of samples: refused, not attempted
  EXPECT_NE(problem(view).find("samples"), std::string::npos);
  view = SurfaceView{};
  view.x_min = NAN;
  EXPECT_NE(problem(view).find("x_min"), std::string::npos);
  try {
    (void)draw_floating_horizon(function_of("x"), view, SurfaceScreen{});
    ADD_FAILURE() << "a NaN x_min was drawn";
  } catch (const PreconditionError& e) {
    EXPECT_EQ(e.code(), Code::usage_error);
  }
  EXPECT_TRUE(check_surface_request(SurfaceView{}, SurfaceScreen{}).ok());
}

}  // namespace
}  // namespace roomcad
