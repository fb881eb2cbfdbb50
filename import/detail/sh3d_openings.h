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

/// Door or window: a name or catalog id containing "door" (any case), or an item that starts
/// at the floor (elevation <= 1 cm) and is at least 1.8 m high (French windows, hatches one can
/// walk through), is a door; everything else is a window.
[[nodiscard]] OpeningType classify_item(const ItemRecord& item);

/// Where the openings' walls stand: what place_openings needs besides the walls.
struct Placement {
  const std::vector<PlacedLevel>& levels;           ///< the plan's levels (place_levels)
  double z_shift_cm = 0.0;                          ///< the shift given to convert_walls
  double chord_tolerance = kDefaultChordTolerance;  ///< metres, for curved cut-out shapes
  const Polygon* outline = nullptr;                 ///< (set per item) its cut-out shape, v up
};

/// Converts items to openings. Each is given to a wall by geometry, as Sweet Home 3D itself
/// does: among the straight pieces (an arc's chords) of walls on the item's level (or a level
/// at its elevation: Sweet Home 3D's layers) that are
/// parallel to it (within 5 degrees), whose span holds the item's centre and whose centre line
/// is within half the wall's thickness plus half the item's depth (+ 1 cm) of the centre, one
/// that holds the item's whole width if any does, and of those the nearest. Like Sweet Home
/// 3D, an item cuts every wall it passes through: its host wall (opening id = the item's id)
/// and any other parallel wall its cut-out box overlaps, on any level (ids `<id>-2`, `<id>-3`,
/// ...), each piece clipped to its wall and under its (sloped) top; its offset is measured
/// along the wall's polyline. A cut-out shape (`cutOutShape`) becomes the opening's `shape`.
/// Warnings (appended to `warnings`, each naming the item): `import_skipped_opening` for an
/// item with no host (it is left out), `import_split_opening` for an item cut in pieces,
/// `import_cut_out_shape` for a cut-out path that does not read (imported as its rectangle).
/// @return the openings, in file order of their items. O(items x chords).
[[nodiscard]] std::vector<Opening> place_openings(const std::vector<ItemRecord>& items,
                                                  const std::vector<PlacedWall>& walls,
                                                  const Placement& placement, Report& warnings);

}  // namespace roomcad::sh3d
