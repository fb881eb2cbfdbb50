// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assert.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"

namespace roomcad::core_detail {

void assertion_failed(const char* condition, const char* why, const char* file, int line) {
  const std::string message = "internal error: " + std::string(file) + ":" + std::to_string(line) +
                              ": " + condition + " (" + why + ")";
#ifdef NDEBUG
  throw PreconditionError(message, Code::internal);
#else
  std::fprintf(stderr, "roomcad: %s\n", message.c_str());
  std::abort();
#endif
}

}  // namespace roomcad::core_detail
