// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assert.h"

#include <cstdio>
#include <cstdlib>

namespace roomcad::core_detail {

void assertion_failed(const char* condition, const char* why, const char* file, int line) {
  std::fprintf(stderr, "roomcad: internal error: %s:%d: %s (%s)\n", file, line, condition, why);
  std::abort();
}

}  // namespace roomcad::core_detail
