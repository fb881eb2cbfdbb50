// SPDX-License-Identifier: GPL-3.0-or-later
// RC_ASSERT(condition, why): an internal invariant, what the code around it relies on and no
// input can make false (as Manifold's DEBUG_ASSERT and CGAL_assertion). Input that can be wrong
// is checked always and reported as an Error with its own code instead.
//
// It is checked in every build, at the cost of one branch, and a broken invariant is never
// run past:
//   - without NDEBUG (the sanitized and fuzz builds, a Debug build) it prints
//     "roomcad: internal error: <file>:<line>: <condition> (<why>)" and aborts, so that the
//     sanitizers and the fuzzers stop at the spot, with its stack;
//   - with NDEBUG (Release) it throws PreconditionError with Code::internal and that message,
//     which a command reports (exit 2) and Python raises.
#pragma once

namespace roomcad::core_detail {
/// Aborts or throws as the header says. Never returns.
[[noreturn]] void assertion_failed(const char* condition, const char* why, const char* file,
                                   int line);
}  // namespace roomcad::core_detail

#define RC_ASSERT(condition, why)                    \
  (__builtin_expect(static_cast<bool>(condition), 1) \
       ? static_cast<void>(0)                        \
       : ::roomcad::core_detail::assertion_failed(#condition, why, __FILE__, __LINE__))
