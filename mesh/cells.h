// SPDX-License-Identifier: GPL-3.0-or-later
// Cells and portals: the closed spaces of a built model (rooms, per storey) and the holes
// between them, so that a renderer draws from the camera's cell only what its portals let
// through (render/portal_walk.h). Built by build_model with BuildOptions::cells
// (solid/detail/cells/find_cells.h explains how and why the walk they allow is conservative).
//
// A cell is a vertical prism: a bounded face of the complement of the walls standing through one
// band of heights (a storey, or part of one), from the band's bottom to its top. Rays from
// inside it leave only through its portals: the holes of the openings in its walls, and its top
// and bottom when no slab closes them (onto the cells of the band above or below, or onto what
// no cell holds). Everything is in world metres, doubles.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/box.h"
#include "plan/plan.h"

namespace roomcad {

/// A hole through a wall: the box the opening's hole cuts, grown by a millimetre every way.
struct Portal {
  std::array<Vec3, 8> corners{};     ///< the grown box's corners
  Box3 bounds = empty_box3();        ///< of the corners
  std::vector<std::uint32_t> cells;  ///< the cells it opens (it is an exit of each)
  bool to_outside = false;  ///< it also opens onto what no cell holds: anything may be seen
};

/// One closed space.
struct Cell {
  Polygon outline;               ///< counter-clockwise
  std::vector<Polygon> islands;  ///< walls standing inside it (clockwise)
  double floor_z = 0.0;          ///< the storey's floor: the walls' base
  double top_z = 0.0;            ///< the lowest top of the walls around it
  /// The eye may stand in the cell between these heights: above any slab under it and below
  /// any slab over it (an eye inside a slab would see through its culled back faces).
  double eye_low = 0.0;
  double eye_high = 0.0;
  bool open_top = true;     ///< no slab closes it from above: top_z is a portal
  bool open_bottom = true;  ///< no slab closes it from below: floor_z is a portal
  /// Through an open top (bottom): the cells of the band of heights above (below) that it
  /// meets, and whether it also opens onto what no cell holds there.
  std::vector<std::uint32_t> cells_above, cells_below;
  bool top_outside = true, bottom_outside = true;
  Box3 bounds = empty_box3();          ///< outline x [floor_z, top_z]
  std::vector<std::uint32_t> portals;  ///< indices into Cells::portals
};

struct Cells {
  std::vector<Cell> cells;
  std::vector<Portal> portals;
  /// Whether slabs close cells (then a scene drawn without slabs cannot use them).
  bool uses_slabs = false;
  [[nodiscard]] bool empty() const { return cells.empty(); }
};

}  // namespace roomcad
