// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces of canonical JSON text: numbers, strings and whole values.
#pragma once

#include <string>
#include <string_view>

#include "io/detail/positioned_json.h"

namespace roomcad::io_detail {

/// Appends the shortest decimal that reads back to exactly `x`: integers below 1e15 in plain
/// digits, otherwise std::to_chars' shortest round-trip form; -0 is written "-0". A value that
/// is not finite (JSON cannot hold it) is written `null`.
void append_number(std::string& out, double x);

/// Appends `s` as a JSON string: quotes, backslashes and control characters escaped, other
/// UTF-8 bytes as they are.
void append_string(std::string& out, std::string_view s);

/// Appends the canonical text of a JSON value on one line: `{"a": 1, "b": [1, 2]}`, object
/// keys sorted, integers as integers, other numbers by append_number.
void append_canonical(std::string& out, const Json& value);

/// @return append_canonical of `value` as a string.
[[nodiscard]] std::string canonical_text(const Json& value);

}  // namespace roomcad::io_detail
