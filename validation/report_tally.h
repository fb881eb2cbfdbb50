// SPDX-License-Identifier: GPL-3.0-or-later
// How many findings of each code and on each level: the summary that ends a long text report,
// so that a plan with hundreds of findings reads as a few lines first.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad {

/// Errors and warnings of one group of findings: a code, or a level.
struct FindingCount {
  std::string name;
  std::size_t errors = 0, warnings = 0;
};

/// Counts `item` in the group `name` of `counts`, added after the others when new (groups stay
/// in the order of their first item). O(groups).
void count_finding(std::vector<FindingCount>& counts, std::string_view name,
                   const Diagnostic& item);

/// @return the level of each item of `report`, in order: that of its first object on a level
/// (a wall's own, an opening's wall's, a slab's), or "" where none is. O(n + m) for n items
/// and m objects.
[[nodiscard]] std::vector<std::string> item_levels(const Report& report, const Plan& plan);

/// @return the summary lines: `by code:` then one line per code (`  wall_overlap  12 errors`,
/// codes in the order of their first item), and, when some item has a level, `by level:`
/// then one line per level in the order of their first item (`  ground  10 errors, 2
/// warnings`; items on no level as `(no level)`). @pre levels.size() == report.items.size()
/// or levels is empty (no level part). O(n k) for k codes and levels.
[[nodiscard]] std::string format_report_tally(const Report& report,
                                              const std::vector<std::string>& levels);

}  // namespace roomcad
