// SPDX-License-Identifier: GPL-3.0-or-later
// "Did you mean ...?": the known name nearest to a misspelt one, for messages about unknown
// fields and keys.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace roomcad {

/// Levenshtein distance (insertions, deletions, substitutions). O(|a| |b|).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

/// @return the first of `names` nearest to `name`, if at most `max_distance` edits away.
///         O(sum of |name| |names[i]|).
[[nodiscard]] std::optional<std::string_view> nearest_name(std::string_view name,
                                                           std::span<const std::string_view> names,
                                                           std::size_t max_distance = 2);

}  // namespace roomcad
