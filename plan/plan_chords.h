// SPDX-License-Identifier: GPL-3.0-or-later
// A plan whose arc walls are the chords they are built as (arc_chords.h), for the code written
// for straight walls: validation's exact verdicts, floor plans. Each chord keeps its wall's id.
#pragma once

#include <cstddef>
#include <vector>

#include "plan/plan.h"

namespace roomcad {

/// @return the length (metres, in doubles) of the polyline `points`. O(points).
[[nodiscard]] double polyline_length(const std::vector<Point2>& points);

/// @return whether `wall` is an arc that can be built: finite ends, from != to,
///         0 < |arc_extent| < 360 and at most kMaxChords chords within `chord_tolerance`. O(1).
[[nodiscard]] bool is_buildable_arc(const Wall& wall, double chord_tolerance);

/// @return one wall per segment of `line` (the chord polyline of arc wall `w`), each a copy of
///         `w` (id and fields kept, arc_extent dropped) with its share of a sloped top: the
///         height interpolated along the polyline at its two ends, the first starting at
///         `height` and the last ending at `height_at_end` exactly. O(line).
[[nodiscard]] std::vector<Wall> chord_walls(const Wall& w, const std::vector<Point2>& line);

/// A plan whose arc walls are their chords, and where each object came from.
struct ChordPlan {
  Plan plan;
  std::vector<std::size_t> source_wall;     ///< by wall of `plan`: its index in the input
  std::vector<std::size_t> source_opening;  ///< by opening of `plan`: its index in the input
  /// By opening of `plan`: for a piece of an arc wall's opening, the index of its chord in
  /// `plan.walls`; kNoChord for an opening that is not cut.
  std::vector<std::size_t> chord;
};

inline constexpr std::size_t kNoChord = static_cast<std::size_t>(-1);

/// `plan` with each buildable arc wall replaced by its chords (chord_polyline), each keeping
/// the wall's id, fields and its share of a sloped top (heights interpolated along the
/// polyline); the openings of an arc wall cut into one piece per chord their outline's extent
/// (along the polyline and up) crosses, each the rectangle of that extent on its chord, with
/// the opening's id. An arc that cannot be built stays a straight wall from `from` to `to`
/// (validation reports its value). Everything else is copied.
/// O(walls + chords + openings x chords).
[[nodiscard]] ChordPlan with_arcs_as_chords(const Plan& plan);

}  // namespace roomcad
