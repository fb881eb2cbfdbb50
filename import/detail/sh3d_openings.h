// SPDX-License-Identifier: GPL-3.0-or-later
// Sweet Home 3D doors and windows to plan openings. The file does not say which wall holds a
// door or window, so each is given to a wall by geometry, as Sweet Home 3D itself does.
#pragma once

#include <optional>
#include <vector>

#include "import/detail/sh3d_home.h"
#include "import/detail/sh3d_walls.h"
#include "validation/report.h"

namespace roomcad::sh3d {

struct HostOptions {
  double max_angle_deg = 5.0;  ///< largest angle between an item's width axis and a wall
  double slack = 0.01;         ///< metres allowed beyond the wall's half thickness + half depth
  double min_piece = 1e-3;     ///< metres: thinner overlaps of a cut-out and a wall are ignored
};

/// The wall that holds `item`: among walls on the item's level that are parallel to it (within
/// `max_angle_deg`, either way round), whose span holds the item's centre and whose centre line
/// is within half the wall's thickness plus half the item's depth (+ slack) of the centre, one
/// that holds the item's whole width if any does, and of those the one whose centre line is
/// nearest the item's centre.
/// @return its index in `walls`, or nullopt when no wall qualifies. O(walls).
[[nodiscard]] std::optional<std::size_t> find_host_wall(const ItemRecord& item,
                                                        const std::vector<PlacedWall>& walls,
                                                        const HostOptions& options = {});

/// Door or window: a name or catalog id containing "door" (any case), or an item that starts
/// at the floor (elevation <= 1 cm) and is at least 1.8 m high (French windows, hatches one can
/// walk through), is a door; everything else is a window.
[[nodiscard]] OpeningType classify_item(const ItemRecord& item);

/// Converts items to openings. Like Sweet Home 3D, an item cuts every wall it passes through:
/// its host wall (opening id = the item's id) and any other parallel wall its cut-out box
/// overlaps, on any level (ids `<id>-2`, `<id>-3`, ...; e.g. a door across the joint of two
/// collinear walls, a window taller than its storey), each piece clipped to its wall.
/// Warnings (appended to `warnings`, each naming the item): `import_skipped_opening` for an
/// item with no host (it is left out), `import_split_opening` for an item cut in pieces,
/// `import_cut_out_shape` for a non-rectangular cut-out (imported as its bounding rectangle,
/// the whole wall part of the item). `z_shift_cm` is the shift given to convert_walls.
/// @return the openings, in file order of their items. O(items x walls).
[[nodiscard]] std::vector<Opening> place_openings(const Home& home,
                                                  const std::vector<ItemRecord>& items,
                                                  const std::vector<PlacedWall>& walls,
                                                  double z_shift_cm, Report& warnings);

}  // namespace roomcad::sh3d
