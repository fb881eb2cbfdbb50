// SPDX-License-Identifier: GPL-3.0-or-later
// The fast path at T joins: a stem whose end lies on the middle of a through-wall standing on
// the same base, as high as it or lower, is clipped at the through-wall's face (its end
// corners are the crossings of its side lines with that face, and it gets no cap), and the
// through-wall's face gets the attachment gap, up to the stem's top, with those very corners.
// Valid when the stem meets the through-wall at 30 degrees or more, its square end lies inside
// the through-wall (what the clip takes off is inside it), only that wall joins the stem at
// that end, and the gap stays clear of the through-wall's ends, holes and other stems.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

struct Tee {
  std::size_t stem = 0;
  WallEnd end = WallEnd::from;  ///< the stem's end on the through-wall
  std::size_t through = 0;
  Attachment attachment;       ///< the gap in the through-wall's face
  std::array<Point2, 2> clip;  ///< the stem's new corners at `end`: right, left (seen outward)
};

/// Finds the T joins the fast path can build, among unite joins between walls of equal base
/// and height. `frames` must already carry any hub attached (their ends are final).
/// @return tees in join order, their attachments non-overlapping. O(k log k) for k joins.
[[nodiscard]] std::vector<Tee> find_tees(const std::vector<WallFrame>& frames, const Joins& joins);

/// Clips each stem and gives each through-wall its attachment gap.
void attach_tees(const std::vector<Tee>& tees, std::vector<WallFrame>& frames);

}  // namespace roomcad::detail
