// SPDX-License-Identifier: GPL-3.0-or-later
// How many random plans a stress test runs: a documented default, or ROOMCAD_STRESS_PLANS.
#pragma once

#include <cstdint>

namespace roomcad::test {

/// The default count of stress plans: the normal suite runs all of them.
inline constexpr std::uint64_t kDefaultStressPlans = 1000;

/// The number of random plans a stress test runs: ROOMCAD_STRESS_PLANS if set (the sanitized
/// suite sets it lower, as a plan's build costs ~35x more under AddressSanitizer), otherwise
/// kDefaultStressPlans. Prints the count used, and where it came from, to stdout, so a
/// shortened run is never mistaken for a full one.
/// @return a count of at least 1.
/// @throws std::invalid_argument if the variable is set but not an integer in [1, 10^6],
///         naming the variable and its value.
/// Cost: one getenv.
[[nodiscard]] std::uint64_t stress_plan_count();

}  // namespace roomcad::test
