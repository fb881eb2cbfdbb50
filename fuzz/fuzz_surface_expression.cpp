// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the surface expression parser and its evaluator on arbitrary text. Any
// crash, sanitizer report, uncaught exception, leak or hang is a bug; so is an error column
// outside [1, size + 1] (parse_surface_expression's contract).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "render/surface_expression.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto parsed = roomcad::parse_surface_expression(text);
  if (!parsed) {
    const std::size_t column = parsed.error().location->column;
    if (parsed.code() != roomcad::Code::parse_error || column < 1 || column > size + 1)
      __builtin_trap();
    return 0;
  }
  const roomcad::SurfaceExpression& expression = parsed.value();
  for (const double x : {-2.5, 0.0, 1.0, 1e300}) {
    for (const double z : {-1.0, 0.0, 3.5}) {
      const double y = expression.evaluate(x, z);
      if (std::isinf(y)) __builtin_trap();  // not finite must come back as NaN
    }
  }
  return 0;
}
