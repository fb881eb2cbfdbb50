// SPDX-License-Identifier: GPL-3.0-or-later
// Every geometric code with a positive case and a just-clear negative case, in every frame
// of all_frames() (see Frame for why the verdicts stay well defined there), plus exact
// touching in the frames that keep the numbers exact.
#include <gtest/gtest.h>

#include "margin_cases.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;

TEST(Exactness, MicrometreOverlapAndGapAreToldApartInEveryFrame) {
  for (const MarginCase& c : margin_cases())
    for (const Frame& f : all_frames()) {
      SCOPED_TRACE(::testing::Message() << c.name << ", frame " << f.degrees << " deg + ("
                                        << f.offset.x << ", " << f.offset.y << ")");
      EXPECT_EQ(error_codes(validate(f.apply(c.build(1e-6)), no_rooms())), c.when_overlapping);
      EXPECT_EQ(error_codes(validate(f.apply(c.build(-1e-6)), no_rooms())), Codes{});
    }
}

TEST(Exactness, TouchingIsNotOverlappingWhereTheNumbersAreExact) {
  for (const MarginCase& c : margin_cases())
    for (const Frame& f : {Frame{0, {0, 0}}, Frame{0, {1048576.0, -1048576.0}}}) {
      SCOPED_TRACE(::testing::Message() << c.name << ", offset " << f.offset.x);
      EXPECT_EQ(error_codes(validate(f.apply(c.build(0)), no_rooms())), Codes{});
    }
}

}  // namespace
}  // namespace roomcad
