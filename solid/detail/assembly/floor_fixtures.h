// SPDX-License-Identifier: GPL-3.0-or-later
// The parts of the model that need no boolean: the tiled floor and the fixtures (door leaves
// and window panes as thin boxes set in their holes).
#pragma once

#include <span>

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

/// The site's floor: cells[0] x cells[1] square tiles of cell_size from origin, at z = 0,
/// facing up, sharing vertices; tiles alternate between floor_color and a 10% darker shade
/// (a checkerboard, so tiles show in pictures).
/// @pre cells positive, cell_size positive and finite (validate).
/// @return one quad per tile, object -1. O(cells[0] x cells[1]).
/// @throws PreconditionError if the site is degenerate or has more than 10^7 tiles.
[[nodiscard]] FaceSoup build_floor(const Site& site);

/// Door leaves and window panes, one closed box (6 quads) per opening.
/// A window pane is 20 mm thick (at most the wall's thickness), centred in the wall, filling
/// the hole. A door leaf is 40 mm thick, as wide and high as the hole, shown open at 90
/// degrees: hinged at the hole's start (u = offset) for `hinge: left` or its end for `right`,
/// standing out of the wall's left face (the side of the normal, `swing: in`) or right face.
/// @return one soup per opening (fixtures may touch, so they share no vertices), faces with
///         kind door or window and the opening's object. O(openings).
[[nodiscard]] std::vector<FaceSoup> build_fixtures(const Plan& plan,
                                                   std::span<const WallFrame> frames);

}  // namespace roomcad::detail
