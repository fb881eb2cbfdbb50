// SPDX-License-Identifier: GPL-3.0-or-later
// Sweet Home 3D walls to plan walls (plan format version 2): on their levels, with their sloped
// tops and arcs, and joined end points made to coincide exactly.
#pragma once

#include <string>
#include <vector>

#include "import/detail/sh3d_home.h"
#include "import/detail/sh3d_levels.h"
#include "validation/report.h"

namespace roomcad::sh3d {

/// `metres` rounded to a multiple of 2^-20 m (under a micrometre): sums and differences of
/// such values below 2^32 m are exact in double precision.
[[nodiscard]] double on_dyadic_grid(double metres);

/// The z (metres) of a height given in centimetres, on the dyadic grid. Every wall base and top
/// comes from here, so `base + height` is exact in double
/// precision and a storey's walls stand exactly on the tops of the walls below.
[[nodiscard]] double z_of(double cm);

/// Where the walls of a level start: Sweet Home 3D draws the walls of every level but the lowest
/// down through the floor slab, from `elevation - floorThickness`, so that storeys stack with
/// no gap.
struct LevelBase {
  double base_cm = 0.0;          ///< the walls' bottom
  double floor_offset_cm = 0.0;  ///< the level's elevation minus `base_cm` (the slab they fill)
};

/// @return the base of the walls of level `level_id` ("" for a home without levels).
/// @pre every level id used by the home names one of `home.levels`. O(levels).
[[nodiscard]] LevelBase level_base(const Home& home, const std::string& level_id);

/// A plan wall, the Sweet Home 3D level it stands on and where it is.
struct PlacedWall {
  Wall wall;
  std::string level;             ///< Sweet Home 3D level id
  double base_z = 0.0;           ///< absolute z of its base, metres
  std::vector<Point2> polyline;  ///< its centre line as built (an arc's chords: chord_polyline)
};

/// @return a warning of `code` about the object `id` (io's own codes start with `import_`).
[[nodiscard]] Diagnostic import_warning(Code code, const std::string& id, std::string message);

struct WallOptions {
  double chord_tolerance = kDefaultChordTolerance;  ///< the plan's, for arcs' polylines
  double snap_distance = 1e-3;  ///< end points closer than this are made equal, metres
  double z_shift_cm = 0.0;      ///< added to every elevation (raises a basement to z >= 0)
};

/// Converts `walls` (a selection of `home.walls`, in file order) to plan walls, one per
/// `<wall>`: on its plan level (`levels`, from place_levels) and reaching down through the
/// level's floor as in Sweet Home 3D, with its sloped top (`height_at_end`) and its arc
/// (`arc_extent`, the sign turned: Sweet Home 3D's positive arcs turn clockwise once y points
/// north). A wall of zero length is left out with an `import_zero_length_wall` warning.
/// @return the placed walls, in file order. O(walls^2) (junctions) + O(chords).
[[nodiscard]] std::vector<PlacedWall> convert_walls(const Home& home, std::vector<WallRecord> walls,
                                                    const std::vector<PlacedLevel>& levels,
                                                    const WallOptions& options, Report& warnings);

}  // namespace roomcad::sh3d
