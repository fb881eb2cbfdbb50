// SPDX-License-Identifier: GPL-3.0-or-later
// validate() on random plans (any geometry, awkward numbers): it never throws, it says the
// same thing twice, and every item is a known code with a message.
#include <set>

#include <gtest/gtest.h>

#include "testing/random_plan.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

const std::set<Code> kCodes = {
    Code::invalid_value,    Code::duplicate_id,         Code::unknown_reference,
    Code::wall_overlap,     Code::opening_outside_wall, Code::opening_overlap,
    Code::opening_blocked,  Code::out_of_bounds,        Code::unknown_field,
    Code::door_above_floor, Code::room_without_door,    Code::room_without_window};

TEST(Robustness, RandomPlansAreReportedNotCrashedOn) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE(seed);
    samples::RandomPlanOptions options;
    options.awkward_numbers = seed % 2 == 0;
    const Plan plan = samples::random_plan(seed, options);
    Report first;
    ASSERT_NO_THROW(first = validate(plan));
    EXPECT_TRUE(validate(plan).items == first.items) << "not deterministic";
    for (const Diagnostic& d : first.items) {
      EXPECT_TRUE(kCodes.contains(d.code)) << d.code;
      EXPECT_FALSE(d.message.empty());
    }
    ASSERT_NO_THROW((void)find_rooms(plan));
  }
}

}  // namespace
}  // namespace roomcad
