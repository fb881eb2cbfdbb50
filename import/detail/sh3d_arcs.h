// SPDX-License-Identifier: GPL-3.0-or-later
// Curved Sweet Home 3D walls as chains of straight walls (chords), with doors and windows kept
// whole: a chord break never falls in an opening, so each opening lies in one straight wall.
#pragma once

#include <vector>

#include "import/detail/sh3d_home.h"

namespace roomcad::sh3d {

/// A circular arc from `start` turning by `sweep` radians about `centre` (positive:
/// counter-clockwise).
struct Arc {
  Point2 centre;
  double radius = 0.0;
  double start_angle = 0.0;  ///< direction from the centre to the arc's start, radians
  double sweep = 0.0;
};

/// The arc from `a` to `b` turning by `extent` radians; a positive extent bulges to the left of
/// a->b (so it turns clockwise about its centre).
/// @pre a != b, 0 < |extent| <= 2 pi. O(1).
[[nodiscard]] Arc arc_through(Point2 a, Point2 b, double extent);

/// A stretch of the arc, as fractions of its sweep, that must lie within one chord.
struct KeepWhole {
  double from = 0.0;
  double to = 0.0;
};

/// The stretches of `wall`'s arc taken by the doors and windows of `items` on its level that sit
/// in it, each widened by `margin` metres on both sides (so that the mitre with the next chord
/// stays clear of the opening).
[[nodiscard]] std::vector<KeepWhole> openings_on_arc(const WallRecord& wall, const Arc& arc,
                                                     const std::vector<ItemRecord>& items,
                                                     double margin);

/// The points where the arc from `a` to `b` turning by `extent` radians is cut into chords no
/// farther than `tolerance` from the arc, except that no cut falls inside a `keep` stretch
/// (a chord holding an opening may stray farther, by its own sagitta).
/// @pre a != b, extent != 0, tolerance > 0.
/// @return the chord end points, first exactly `a` and last exactly `b`. O(chords + keep log keep).
[[nodiscard]] std::vector<Point2> split_arc(Point2 a, Point2 b, double extent, double tolerance,
                                            std::vector<KeepWhole> keep = {});

}  // namespace roomcad::sh3d
