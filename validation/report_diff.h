// Comparing two reports of the same plan before and after an edit: which errors are new.
// Shared by the edit commands (cli/edit_session) and the window (view/), which both judge an
// edit by the errors it introduces rather than by the errors the plan already had.
#pragma once

#include "validation/report.h"

namespace roomcad {

/// The errors of `after` beyond those of `before`, counted per identity: an error's code and
/// the sorted ids it involves (messages and places change when objects move, the problem
/// does not). Two overlaps of the same walls before and one after introduce nothing; warnings
/// are ignored.
/// @return the new errors, in `after`'s order. O(n log n) in items.
[[nodiscard]] Report introduced_errors(const Report& before, const Report& after);

}  // namespace roomcad
