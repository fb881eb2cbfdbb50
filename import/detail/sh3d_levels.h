// SPDX-License-Identifier: GPL-3.0-or-later
// Sweet Home 3D levels as the plan's levels (plan format version 2).
//
// A level keeps its elevation (raised with the whole home, see z_shift), its height, and its
// name as its id where the name is usable. Sweet Home 3D draws the walls of every level but
// the lowest down through the level's floor (from elevation - floorThickness): those walls get
// base = -floorThickness on their level, so that storeys stack with no gap, and the level's
// rooms become floor slabs filling that band.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "import/detail/sh3d_home.h"

namespace roomcad::sh3d {

/// A level of the home and the plan level it becomes.
struct PlacedLevel {
  std::string source_id;         ///< its Sweet Home 3D id
  roomcad::Level level;          ///< the plan's level (elevation already shifted)
  double floor_offset_cm = 0.0;  ///< how far its walls reach below its elevation (0: lowest)
  double floor_thickness_cm = 0.0;
};

/// The plan levels of `levels` (a selection of home.levels, in file order). A level's id is
/// its name when that is not empty and no other level has it and `taken` does not hold it
/// (the ids of the home's other elements), else its Sweet Home 3D id. Its height is its own,
/// else the home's wall height, else 250 cm. `z_shift_cm` is added to every elevation.
/// O(levels log levels).
[[nodiscard]] std::vector<PlacedLevel> place_levels(
    const Home& home, const std::vector<sh3d::Level>& levels, double z_shift_cm,
    const std::set<std::string, std::less<>>& taken);

/// @return the placed level of Sweet Home 3D level `source_id`, or nullptr (a home without
/// levels, or `source_id` empty). O(levels).
[[nodiscard]] const PlacedLevel* find_placed(const std::vector<PlacedLevel>& levels,
                                             const std::string& source_id);

}  // namespace roomcad::sh3d
