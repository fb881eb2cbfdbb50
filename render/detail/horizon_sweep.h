// SPDX-License-Identifier: GPL-3.0-or-later
// The horizon arrays of the floating-horizon method and the clipping of one section's
// segments against them. Coordinates here have y growing upwards (picture plane, scaled).
#pragma once

#include <cstddef>
#include <vector>

#include "render/floating_horizon.h"

namespace roomcad::detail {

/// Upper and lower horizons sampled at `columns + 1` evenly spaced screen columns, "old" ones
/// (sections before the current one, used for visibility) and "new" ones (also holding the
/// current section, adopted when it ends), as in the seed's variant 3. Between columns a
/// horizon is the straight line joining its column values.
class HorizonSweep {
 public:
  /// @param width    screen width; columns sit at x = k * width / columns, k = 0..columns
  /// @param columns  >= 1
  HorizonSweep(double width, int columns);

  /// Starts a section; pieces where the horizons are still unset get `unset_side`.
  void begin_section(HorizonSide unset_side);
  /// Clips the segment [p, t] against the old horizons, keeps its visible pieces, and raises
  /// the new horizons with it. O(columns it spans + 1).
  void add_segment(ScreenPoint p, ScreenPoint t);
  /// Ends the current polyline (a missing sample): the next segment starts a new one.
  void break_polyline() { open_ = false; }
  /// Ends the section: its segments now hide those of later sections.
  void end_section();

  /// @return the visible polylines so far, in the order they were found (y upwards).
  [[nodiscard]] std::vector<HorizonPolyline> take_polylines() { return std::move(polylines_); }

 private:
  struct Piece {
    double s0, s1;  ///< parameters along the segment, s0 < s1
    HorizonSide side;
  };
  void clip_interval(ScreenPoint p, ScreenPoint t, double s0, double s1,
                     std::vector<Piece>& out) const;
  void raise_horizons(ScreenPoint p, ScreenPoint t);
  void keep_piece(ScreenPoint a, ScreenPoint b, HorizonSide side);
  [[nodiscard]] std::size_t column_of(double x) const;

  double pitch_;
  std::vector<double> up_, down_, new_up_, new_down_;
  HorizonSide unset_side_ = HorizonSide::first;
  std::vector<HorizonPolyline> polylines_;
  bool open_ = false;            ///< the last polyline may be extended
  bool last_from_this_ = false;  ///< its last point came from the segment being clipped
};

}  // namespace roomcad::detail
