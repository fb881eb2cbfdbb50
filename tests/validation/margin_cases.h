// SPDX-License-Identifier: GPL-3.0-or-later
// Geometric cases with a signed margin, shared by the exactness and the numerical stress
// tests: each is built in its local frame so that a margin e > 0 overlaps (or pokes out),
// e < 0 leaves a gap and e == 0 touches; the codes expected when overlapping are given.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "plan_cases.h"

namespace roomcad::testing {

struct MarginCase {
  const char* name;
  std::function<Plan(double e)> build;
  std::vector<Code> when_overlapping;
};

/// Every geometric error code with walls `t` metres thick (t well under 1 m).
/// @param t  wall thickness, metres; the cases scale their offsets by it where it matters
/// @return the cases, each a few walls and openings. O(1).
inline std::vector<MarginCase> margin_cases(double t = 0.25) {
  const double h = t / 2;
  auto wall = [t](std::string id, Point2 from, Point2 to) {
    return make_wall(std::move(id), from, to, t);
  };
  return {
      {"parallel walls side by side",
       [=](double e) {
         return plan_with({wall("a", {0, 0}, {4, 0}), wall("b", {0, 2 * h - e}, {4, 2 * h - e})});
       },
       {Code::wall_overlap}},
      {"wall end against the side of another, not joined",
       [=](double e) {
         return plan_with({wall("a", {0, 0}, {4, 0}), wall("b", {2, h - e}, {2, 3})});
       },
       {Code::wall_overlap}},
      {"window past the end of its wall",
       [=](double e) {
         return plan_with({wall("s", {0, 0}, {4, 0})},
                          {make_opening("w", OpeningType::window, "s", 3, 1 + e, 1, 0.9)});
       },
       {Code::opening_outside_wall}},
      {"window above the top of its wall",
       [=](double e) {
         return plan_with({wall("s", {0, 0}, {4, 0})},
                          {make_opening("w", OpeningType::window, "s", 1, 1, 1.5 + e, 1)});
       },
       {Code::opening_outside_wall}},
      {"two windows side by side",
       [=](double e) {
         return plan_with({wall("s", {0, 0}, {4, 0})},
                          {make_opening("w1", OpeningType::window, "s", 0.5, 1, 1, 0.9),
                           make_opening("w2", OpeningType::window, "s", 1.5 - e, 1, 1, 0.9)});
       },
       {Code::opening_overlap}},
      {"door in the bar of a T next to the stem",
       [=](double e) {
         return plan_with({wall("a", {0, 0}, {4, 0}), wall("b", {2, 0}, {2, 3})},
                          {make_opening("d", OpeningType::door, "a", 0.5, 2 - h - 0.5 + e, 2, 0)});
       },
       {Code::opening_blocked}},
      {"door in the stem of a T next to the bar",
       [=](double e) {
         return plan_with({wall("a", {0, 0}, {4, 0}), wall("b", {2, 0}, {2, 3})},
                          {make_opening("d", OpeningType::door, "b", h - e, 1, 2, 0)});
       },
       {Code::opening_blocked}},
      {"window at a mitred corner",
       [=](double e) {
         return plan_with({wall("a", {0, 0}, {4, 0}), wall("b", {0, 0}, {0, 3})},
                          {make_opening("w", OpeningType::window, "a", h - e, 1, 1, 0.9)});
       },
       {Code::opening_blocked}},
      {"wall resting on top of another, with a window reaching the top",
       [=](double e) {
         // b's footprint overlaps a's in plan, their centre lines 0.4 t apart (not joined);
         // only heights separate them: a is 2.5 m high, b starts at 2.5 - e.
         Plan p = plan_with({wall("a", {0, 0}, {4, 0}), wall("b", {0, 0.4 * t}, {4, 0.4 * t})},
                            {make_opening("w", OpeningType::window, "a", 1, 1, 1, 1.5)});
         p.walls[1].base = 2.5 - e;
         p.walls[1].height = 1;
         return p;
       },
       {Code::wall_overlap, Code::opening_blocked}},
  };
}

}  // namespace roomcad::testing
