// SPDX-License-Identifier: GPL-3.0-or-later
// OnceSlot: a value computed on first need and kept, safe to ask for from many threads.
//
// Why not std::call_once: glibc's pthread_once ends every first call with a futex system
// call, and the exact values behind the general path's predicates (a plane's coefficients, a
// point's homogeneous coordinates) are made by the thousand in a build: those calls were a
// measurable share of it. Here threads that race each compute the value and all but one drop
// theirs: the computation must be pure (the same value whoever makes it).
#pragma once

#include <atomic>
#include <memory>

namespace roomcad::detail {

template <class T>
class OnceSlot {
 public:
  OnceSlot() = default;
  OnceSlot(const OnceSlot&) = delete;
  OnceSlot& operator=(const OnceSlot&) = delete;
  ~OnceSlot() { delete value_.load(std::memory_order_relaxed); }

  /// @return the value, made by `make()` (returning a T) on the first call. Lock-free; a
  ///         thread that loses a race to publish drops the value it made.
  template <class Make>
  const T& get(Make&& make) const {
    if (const T* known = value_.load(std::memory_order_acquire)) return *known;
    auto made = std::make_unique<T>(make());
    T* expected = nullptr;
    if (value_.compare_exchange_strong(expected, made.get(), std::memory_order_acq_rel))
      return *made.release();
    return *expected;  // another thread published first
  }

 private:
  mutable std::atomic<T*> value_{nullptr};
};

}  // namespace roomcad::detail
