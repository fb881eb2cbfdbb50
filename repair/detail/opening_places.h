// SPDX-License-Identifier: GPL-3.0-or-later
// Keeping openings where they stand in the world when their wall is trimmed, moved off or
// removed: each goes to the wall as edited, or to the wall of the same line and thickness that
// now holds its place (its hole is then the same prism), with its id.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "repair/repair.h"

namespace roomcad::detail {

struct Placement {
  std::vector<RepairEdit> edits;  ///< one per opening whose fields change
  std::string refusal;            ///< non-empty: an opening has no wall to stand on
};

/// Places the openings `openings` (indices into plan.openings) of wall `old_host` on
/// `new_host` (the same wall after its edit; nullopt when it is removed) or else on `other`
/// when it lies on the same line (within `tolerance`) with the same thickness. An opening that
/// would land inside one of `other`'s own (`others_openings`; the importer splits one door over
/// walls drawn twice) is removed instead: its hole is already cut. `moves` of each edit is the
/// rounding of its new offset and sill and how far its hole moves across (0 when exact).
/// @pre old_host, new_host and other are plain walls (repair/detail/frame_box.h).
[[nodiscard]] Placement place_openings(const Plan& plan, const std::vector<std::size_t>& openings,
                                       const Wall& old_host, const std::optional<Wall>& new_host,
                                       const Wall& other,
                                       const std::vector<std::size_t>& others_openings,
                                       double tolerance);

}  // namespace roomcad::detail
