// SPDX-License-Identifier: GPL-3.0-or-later
// Sweet Home 3D rooms as slabs (plan format version 2): the floors of the upper levels, and
// the ceilings nothing stands on.
#pragma once

#include <vector>

#include "import/detail/sh3d_levels.h"
#include "validation/report.h"

namespace roomcad::sh3d {

/// The Sweet Home 3D floor thickness of a home without levels (its preferences' default).
inline constexpr double kDefaultFloorThicknessCm = 12.0;

/// The slabs of `rooms` (each on a level of `levels`, or on none for a home without levels):
/// - a room's floor, if shown, on a level above the lowest (one whose walls reach down through
///   its floor): the slab `<room id>` from the level's elevation down by its floor thickness,
///   the band Sweet Home 3D fills. The lowest level's floors lie on the ground, which Sweet
///   Home 3D draws with no thickness: they are not slabs;
/// - with `ceilings`, a room's ceiling, if shown and no floor slab of a higher level could cover it
/// (no such
///   floor's box meets the room's box in the band above the ceiling): the slab
///   `<room id>-ceiling` on the room's level from its height up by its floor thickness (12 cm
///   without levels), so that a top storey is closed as drawn.
/// Outlines are counter-clockwise, repeated points dropped; a room of fewer than 3 distinct
/// points, no area, or an outline that is not simple (a slit around a stair well) is left out
/// with an `import_skipped_element` warning.
/// `base_z` is the z of the floor of a home without levels. O(rooms^2).
[[nodiscard]] std::vector<Slab> make_slabs(const Home& home, const std::vector<RoomRecord>& rooms,
                                           const std::vector<PlacedLevel>& levels, double base_z,
                                           bool ceilings, Report& warnings);

/// The names of `rooms` (`plan.rooms`): for each room with a name and an outline of some area,
/// the label `<room id>-name` with that name, on the room's level, at a point inside its
/// outline (the middle of the widest run inside it along the line halfway up its box), so
/// that validation knows a bath from a bedroom. O(points).
[[nodiscard]] std::vector<RoomLabel> make_room_labels(const std::vector<RoomRecord>& rooms,
                                                      const std::vector<PlacedLevel>& levels);

}  // namespace roomcad::sh3d
