// Generated plans for benchmarks: grids of rooms, shared by the validation, modeling and
// render benchmarks.
#pragma once

#include <cstddef>

#include "modeling/plan.h"

namespace roomcad::bench {

struct GridOptions {
  std::size_t columns = 10;     ///< rooms along x
  std::size_t rows = 10;        ///< rooms along y
  double room_size = 4.0;       ///< centre-line spacing, metres
  double thickness = 0.2;
  double height = 2.8;
  bool openings = true;         ///< a door in every interior wall, a window in every exterior one
};

/// A grid of columns x rows square rooms. Walls are one segment per room side, meeting at
/// the grid nodes (mitres at the four outer corners, T and X junctions elsewhere), so there
/// are columns * (rows + 1) + rows * (columns + 1) walls and as many openings. The plan is
/// valid: validation reports no errors (only room_without_window for inner rooms).
/// O(walls).
[[nodiscard]] Plan make_grid_plan(const GridOptions& options);

/// @return the number of walls make_grid_plan makes for these options.
[[nodiscard]] std::size_t grid_wall_count(const GridOptions& options);

}  // namespace roomcad::bench
