// SPDX-License-Identifier: GPL-3.0-or-later
// JSON values as the plan reader's messages show them ("an array of 3 items", a string quoted
// and cut), and the whole text of a value.
#pragma once

#include <simdjson.h>

#include <string>
#include <string_view>

#include "io/detail/positioned_json.h"

namespace roomcad::io_detail {

/// Thrown when the text is not the JSON the reader accepts (malformed, or a duplicate key):
/// read_plan_document then reports the positioned parser's precise message instead.
struct Malformed {};

/// A string as a message shows it: quoted, escaped, cut after 40 bytes (whole characters).
[[nodiscard]] std::string quote_for_message(std::string_view text);

/// "an object", "an array of 3 items", "\"abc\"", "12.5": how a found value is shown.
/// @throws Malformed where a number or literal does not parse.
[[nodiscard]] std::string describe(simdjson::ondemand::value& v);

/// describe, for a whole document read by the positioned parser.
[[nodiscard]] std::string describe_json(const Json& v);

/// @return the whole text of a value (consuming it).
[[nodiscard]] std::string_view raw_json(simdjson::ondemand::value& v);

}  // namespace roomcad::io_detail
