// SPDX-License-Identifier: GPL-3.0-or-later
// Proposals for slab_overlap: the later slab's area cut back by the earlier one's, an exact 2D
// difference rounded once (no slab grows). The cut keeps the union when the later slab's
// height lies within the earlier one's, and otherwise moves the solid by what it reaches out.
#pragma once

#include "repair/detail/context.h"
#include "repair/detail/proposal.h"

namespace roomcad::detail {

/// @pre finding.code == slab_overlap.
[[nodiscard]] Attempt propose_slab_cut(const RepairContext& ctx, const Diagnostic& finding);

}  // namespace roomcad::detail
