// SPDX-License-Identifier: GPL-3.0-or-later
// JSON values written by hand in the commands' outputs (info, insolation): a string escaped,
// a number as the shortest decimal that reads back the same.
#pragma once

#include <string>
#include <string_view>

namespace roomcad::cli {

/// @return `s` as a JSON string: quotes, backslashes and control characters escaped. O(n).
[[nodiscard]] std::string json_string(std::string_view s);

/// @return the shortest decimal that reads back as `x`, or `null` when `x` is not finite.
[[nodiscard]] std::string json_number(double x);

}  // namespace roomcad::cli
