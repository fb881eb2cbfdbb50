// SPDX-License-Identifier: GPL-3.0-or-later
#include "support/stress_plans.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace roomcad::test {

std::uint64_t stress_plan_count() {
  constexpr std::uint64_t kMost = 1'000'000;  // beyond this a typo, not a plan for a run
  const char* text = std::getenv("ROOMCAD_STRESS_PLANS");
  if (text == nullptr || *text == '\0') {
    std::printf("stress plans: %llu (the default; ROOMCAD_STRESS_PLANS is not set)\n",
                static_cast<unsigned long long>(kDefaultStressPlans));
    return kDefaultStressPlans;
  }
  const std::string_view value(text);
  std::uint64_t count = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), count);
  if (error != std::errc{} || end != value.data() + value.size() || count < 1 || count > kMost)
    throw std::invalid_argument("environment variable ROOMCAD_STRESS_PLANS: \"" +
                                std::string(value) + "\" is not a count from 1 to " +
                                std::to_string(kMost));
  std::printf("stress plans: %llu (from ROOMCAD_STRESS_PLANS; the default is %llu)\n",
              static_cast<unsigned long long>(count),
              static_cast<unsigned long long>(kDefaultStressPlans));
  return count;
}

}  // namespace roomcad::test
