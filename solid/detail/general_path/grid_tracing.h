// SPDX-License-Identifier: GPL-3.0-or-later
// Tracing on a plane's grid (grid_faces.h): each owner's cells, on one side of the plane, become
// closed loops along the grid lines, turning left where two of its cells touch at a corner
// only, so that no loop passes a point twice; a region with a hole is cut along the grid line
// through the hole's top, so every face is one simple polygon with no new line. Integer work
// only: no exact predicate is evaluated here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "solid/detail/general_path/plane_faces.h"

namespace roomcad::detail::grid {

// Directions along the grid, counter-clockwise: a left turn adds 1.
enum Dir : std::uint8_t { east, north, west, south };

// A unit step along a grid line, from grid point `from` (v * lines of constant u + u).
struct Step {
  std::uint32_t from;
  Dir dir;
};

// One side's faces of one owner: its cells, within its box of cells.
struct Region {
  int side;  // +1: faces looking along the plane's normal, -1: against it
  long owner;
  std::uint32_t u0, u1, v0, v1;      // cells [u0, u1) x [v0, v1)
  std::vector<std::uint32_t> cells;  // in order of v, then u
};

// Cells and points of the grid of the plane's view axes u (i) and v (j).
struct Grid {
  std::size_t nu, nv;              // lines of constant u, of constant v
  std::vector<FaceOwners> owners;  // per cell, v * (nu - 1) + u
  // Per grid point: whether a polygon's edge of constant u (of constant v) passes through it or
  // ends there; a face's edge of constant v (u) is split there.
  std::vector<char> on_u_line, on_v_line;

  [[nodiscard]] std::size_t cell(std::uint32_t u, std::uint32_t v) const {
    return v * (nu - 1) + u;
  }
  [[nodiscard]] std::uint32_t point(std::uint32_t u, std::uint32_t v) const {
    return std::uint32_t(v * nu + u);
  }
  [[nodiscard]] std::uint32_t u_of(std::uint32_t point) const { return std::uint32_t(point % nu); }
  [[nodiscard]] std::uint32_t v_of(std::uint32_t point) const { return std::uint32_t(point / nu); }
  [[nodiscard]] std::uint32_t end(const Step& s) const {
    switch (s.dir) {
      case east: return s.from + 1;
      case north: return std::uint32_t(s.from + nu);
      case west: return s.from - 1;
      case south: return std::uint32_t(s.from - nu);
    }
    return s.from;
  }
  [[nodiscard]] long owner(std::size_t cell, int side) const {
    return side > 0 ? owners[cell].up : owners[cell].down;
  }
};

// Scratch space per grid point for tracing regions, each entry left as found.
struct TraceScratch {
  std::vector<std::uint32_t> starts;  // link's
  std::vector<char> marked;           // split_at_repeats'
};

/// The regions, in the order PlaneBoolean files its face groups: side, then owner.
std::vector<Region> find_regions(const Grid& g);

/// The region's loops, each passing a point once; where some are holes, the region is cut along
/// the line of constant v through each hole's top and traced again. None if holes remain.
std::optional<std::vector<std::vector<Step>>> region_loops(const Grid& g, const Region& r,
                                                           TraceScratch& scratch);

/// The grid points of a face: the loop's corners and the points where another polygon's edge
/// crosses or ends on it, counter-clockwise in the grid (u, v).
std::vector<std::uint32_t> face_corners(const Grid& g, const std::vector<Step>& loop);

}  // namespace roomcad::detail::grid
