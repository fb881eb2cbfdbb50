// SPDX-License-Identifier: GPL-3.0-or-later
// Checking and repairing UTF-8 where text enters a plan from a file that is not JSON (a Sweet
// Home 3D home's XML, an IFC model's STEP): a plan is UTF-8 (docs/plan-format.md), and one
// ill-formed byte copied into an id would make the plan unreadable once written.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace roomcad {

/// @return the offset of the first byte of `text` that does not start a well-formed UTF-8
/// sequence (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF, no truncated
/// sequence), or nullopt when all of `text` is well-formed. Cost: O(size of text).
[[nodiscard]] std::optional<std::size_t> first_ill_formed_utf8(std::string_view text);

/// @return `text` with every byte that does not start a well-formed UTF-8 sequence read as
/// ISO 8859-1 (the byte's value as its code point), so a name written in Latin-1 by an older
/// program keeps its letters. Well-formed text comes back unchanged. Cost: O(size of text).
[[nodiscard]] std::string utf8_from_latin1_where_ill_formed(std::string_view text);

/// @return `text` for a message: ill-formed bytes written as `\xFF`, the rest as it is.
[[nodiscard]] std::string printable_utf8(std::string_view text);

}  // namespace roomcad
