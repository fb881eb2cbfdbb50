// SPDX-License-Identifier: GPL-3.0-or-later
// detail::OnceSlot: threads that race for a value all get the one value published, however
// many of them made one, and a value once made is not made again.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "solid/detail/general_path/once_slot.h"

namespace roomcad::detail {
namespace {

TEST(OnceSlot, RacingThreadsAllGetTheOneValuePublished) {
  for (int trial = 0; trial < 20; ++trial) {
    const OnceSlot<std::vector<int>> slot;
    std::atomic<int> made{0}, ready{0};
    constexpr int kThreads = 8;
    std::vector<const std::vector<int>*> seen(kThreads, nullptr);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        ++ready;
        while (ready.load() < kThreads) std::this_thread::yield();  // start together, to race
        seen[std::size_t(t)] = &slot.get([&] {
          ++made;
          return std::vector<int>(1000, 7);
        });
      });
    for (std::thread& th : threads) th.join();
    for (const auto* value : seen) {
      EXPECT_EQ(value, seen.front());  // one published value, whoever made it
      EXPECT_EQ(value->size(), 1000u);
    }
    EXPECT_GE(made.load(), 1);
    // Made once, it is kept: no further call makes it again.
    const int before = made.load();
    EXPECT_EQ(&slot.get([&] {
      ++made;
      return std::vector<int>{};
    }),
              seen.front());
    EXPECT_EQ(made.load(), before);
  }
}

}  // namespace
}  // namespace roomcad::detail
