// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/transform2d.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace roomcad {
namespace {

/// @return (cos, sin) of `degrees`, exact (0, +-1) for whole multiples of 90.
std::pair<double, double> cos_sin(double degrees) {
  const double turn = std::fmod(degrees, 360.0);  // fmod is exact, so 450 is exactly 90
  if (turn == 0.0) return {1.0, 0.0};
  if (turn == 90.0 || turn == -270.0) return {0.0, 1.0};
  if (turn == 180.0 || turn == -180.0) return {-1.0, 0.0};
  if (turn == 270.0 || turn == -90.0) return {0.0, -1.0};
  const double radians = turn * (std::numbers::pi / 180.0);
  return {std::cos(radians), std::sin(radians)};
}

/// @return the product of a chain, each entry rounded once per product.
Transform2d compose_chain(const std::array<Transform2d, 3>& chain) {
  return compose(compose(chain[0], chain[1]), chain[2]);
}

}  // namespace

std::array<Transform2d, 3> about_point(const Transform2d& linear, Point2 about) {
  return {translate(-about.x, -about.y), linear, translate(about.x, about.y)};
}

Transform2d identity_transform() { return {}; }

Transform2d translate(double dx, double dy) {
  Transform2d t;
  t.m[2] = {dx, dy, 1.0};
  return t;
}

Transform2d rotate(double degrees, Point2 about) {
  const auto [c, s] = cos_sin(degrees);
  Transform2d r;
  r.m[0] = {c, s, 0.0};  // row-vector convention: x' = x c - y s, y' = x s + y c
  r.m[1] = {-s, c, 0.0};
  return compose_chain(about_point(r, about));
}

Transform2d scale(double factor, Point2 about) {
  Transform2d s;
  s.m[0][0] = factor;
  s.m[1][1] = factor;
  return compose_chain(about_point(s, about));
}

Transform2d compose(const Transform2d& first, const Transform2d& then) {
  Transform2d product;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const std::array<double, 3> column{then.m[0][j], then.m[1][j], then.m[2][j]};
      product.m[i][j] = exact_dot(first.m[i], column);
    }
  }
  return product;
}

Point2 apply(const Transform2d& t, Point2 p) {
  const std::array<double, 3> row{p.x, p.y, 1.0};
  return {exact_dot(row, std::array{t.m[0][0], t.m[1][0], t.m[2][0]}),
          exact_dot(row, std::array{t.m[0][1], t.m[1][1], t.m[2][1]})};
}

Point2 apply_to_direction(const Transform2d& t, Point2 v) {
  const std::array<double, 2> row{v.x, v.y};
  return {exact_dot(row, std::array{t.m[0][0], t.m[1][0]}),
          exact_dot(row, std::array{t.m[0][1], t.m[1][1]})};
}

double exact_add(double a, double b) { return exact_dot(std::array{a, b}, std::array{1.0, 1.0}); }

bool is_quarter_turn(double degrees) { return std::fmod(degrees, 90.0) == 0.0; }

}  // namespace roomcad
