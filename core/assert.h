// SPDX-License-Identifier: GPL-3.0-or-later
// RC_ASSERT: an internal invariant, checked in debug builds only (as Manifold's DEBUG_ASSERT
// and CGAL_assertion). It states what the code around it relies on and can never be false for
// any input; input that can be wrong is checked always and reported as an Error instead.
#pragma once

namespace roomcad::core_detail {
/// Prints "roomcad: internal error: <file>:<line>: <condition> (<why>)" and aborts.
[[noreturn]] void assertion_failed(const char* condition, const char* why, const char* file,
                                   int line);
}  // namespace roomcad::core_detail

#ifdef NDEBUG
#define RC_ASSERT(condition, why) static_cast<void>(sizeof(!(condition)))
#else
#define RC_ASSERT(condition, why)                                                      \
  ((condition) ? static_cast<void>(0)                                                  \
               : ::roomcad::core_detail::assertion_failed(#condition, why, __FILE__, __LINE__))
#endif
