// SPDX-License-Identifier: GPL-3.0-or-later
// A line diff of two texts, for showing what an edit would change (--dry-run).
#pragma once

#include <string>
#include <string_view>

namespace roomcad::cli {

/// @return the lines only in `before` prefixed "- ", those only in `after` prefixed "+ ",
///         each run of changes under a header "@@ line N @@" (N counts `after`'s lines from 1);
///         empty if the texts are equal. Common lines are found by longest common subsequence
///         after trimming the common head and tail: O(n m) in the changed region's lines,
///         which falls back to replacing the whole region beyond 4 million line pairs.
[[nodiscard]] std::string diff_lines(std::string_view before, std::string_view after);

}  // namespace roomcad::cli
