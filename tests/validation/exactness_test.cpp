// Every geometric code with a positive case and a just-clear negative case, in every frame
// of all_frames() (see Frame for why the verdicts stay well defined there), plus exact
// touching in the frames that keep the numbers exact.
#include <functional>

#include <gtest/gtest.h>

#include "plan_cases.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;
using Codes = std::vector<std::string>;

/// A case built in its local frame with a signed margin e: e > 0 overlaps (or pokes out),
/// e < 0 leaves a gap, e == 0 touches.
struct Case {
  const char* name;
  std::function<Plan(double e)> build;
  Codes when_overlapping;
};

const double h = 0.125;  // half of the 0.25 m walls

std::vector<Case> cases() {
  return {
      {"parallel walls side by side",
       [](double e) {
         return plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {0, 2 * h - e}, {4, 2 * h - e})});
       },
       {"wall_overlap"}},
      {"wall end against the side of another, not joined",
       [](double e) {
         return plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, h - e}, {2, 3})});
       },
       {"wall_overlap"}},
      {"window past the end of its wall",
       [](double e) {
         return plan_with({make_wall("s", {0, 0}, {4, 0})},
                          {make_opening("w", OpeningType::window, "s", 3, 1 + e, 1, 0.9)});
       },
       {"opening_outside_wall"}},
      {"window above the top of its wall",
       [](double e) {
         return plan_with({make_wall("s", {0, 0}, {4, 0})},
                          {make_opening("w", OpeningType::window, "s", 1, 1, 1.5 + e, 1)});
       },
       {"opening_outside_wall"}},
      {"two windows side by side",
       [](double e) {
         return plan_with({make_wall("s", {0, 0}, {4, 0})},
                          {make_opening("w1", OpeningType::window, "s", 0.5, 1, 1, 0.9),
                           make_opening("w2", OpeningType::window, "s", 1.5 - e, 1, 1, 0.9)});
       },
       {"opening_overlap"}},
      {"door in the bar of a T next to the stem",
       [](double e) {
         return plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, 0}, {2, 3})},
                          {make_opening("d", OpeningType::door, "a", 0.5, 2 - h - 0.5 + e, 2, 0)});
       },
       {"opening_blocked"}},
      {"door in the stem of a T next to the bar",
       [](double e) {
         return plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, 0}, {2, 3})},
                          {make_opening("d", OpeningType::door, "b", h - e, 1, 2, 0)});
       },
       {"opening_blocked"}},
      {"window at a mitred corner",
       [](double e) {
         return plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {0, 0}, {0, 3})},
                          {make_opening("w", OpeningType::window, "a", h - e, 1, 1, 0.9)});
       },
       {"opening_blocked"}},
      {"wall resting on top of another, with a window reaching the top",
       [](double e) {
         // b's footprint overlaps a's in plan, their centre lines 0.1 m apart (not joined);
         // only heights separate them: a is 2.5 m high, b starts at 2.5 - e.
         Plan p = plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {0, 0.1}, {4, 0.1})},
                            {make_opening("w", OpeningType::window, "a", 1, 1, 1, 1.5)});
         p.walls[1].base = 2.5 - e;
         p.walls[1].height = 1;
         return p;
       },
       {"wall_overlap", "opening_blocked"}},
  };
}

TEST(Exactness, MicrometreOverlapAndGapAreToldApartInEveryFrame) {
  for (const Case& c : cases())
    for (const Frame& f : all_frames()) {
      SCOPED_TRACE(::testing::Message() << c.name << ", frame " << f.degrees << " deg + ("
                                      << f.offset.x << ", " << f.offset.y << ")");
      EXPECT_EQ(error_codes(validate(f.apply(c.build(1e-6)), no_rooms())), c.when_overlapping);
      EXPECT_EQ(error_codes(validate(f.apply(c.build(-1e-6)), no_rooms())), Codes{});
    }
}

TEST(Exactness, TouchingIsNotOverlappingWhereTheNumbersAreExact) {
  for (const Case& c : cases())
    for (const Frame& f : {Frame{0, {0, 0}}, Frame{0, {1048576.0, -1048576.0}}}) {
      SCOPED_TRACE(::testing::Message() << c.name << ", offset " << f.offset.x);
      EXPECT_EQ(error_codes(validate(f.apply(c.build(0)), no_rooms())), Codes{});
    }
}

}  // namespace
}  // namespace roomcad
