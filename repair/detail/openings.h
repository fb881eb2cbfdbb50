// SPDX-License-Identifier: GPL-3.0-or-later
// Proposals for the findings of openings: one past its wall's end or top (shortened to fit),
// two overlapping in one wall (the inner one removed, two of one kind and height merged, or
// the later shortened), one blocked by a wall drawn across its side (shortened clear of it).
// Openings whose walls overlap another wait for the wall repairs, which often clear them.
#pragma once

#include "repair/detail/context.h"
#include "repair/detail/proposal.h"

namespace roomcad::detail {

/// @pre finding.code is opening_outside_wall, opening_overlap or opening_blocked.
[[nodiscard]] Attempt propose_opening_fix(const RepairContext& ctx, const Diagnostic& finding);

}  // namespace roomcad::detail
