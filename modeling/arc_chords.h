// SPDX-License-Identifier: GPL-3.0-or-later
// The chord polyline of an arc wall (plan format version 2, `arc_extent`): the wall IS this
// polyline, so the build, validation, drawings and the importer all take it from here and
// agree to the bit.
#pragma once

#include <vector>

#include "modeling/plan.h"

namespace roomcad {

/// Most chords one arc is built as: a 1 km radius turning 359 degrees at 1 mm needs 2,200;
/// beyond this count the sagitta may exceed the tolerance (a finer tolerance buys nothing).
inline constexpr int kMaxArcChords = 4096;

/// The number of equal chords of an arc of `radius` metres turning by `theta` radians: the
/// smallest n whose sagitta radius * (1 - cos(theta / 2n)) is at most `tolerance` metres
/// (docs/plan-format.md, "arc_extent"), at most kMaxArcChords.
/// @pre radius > 0, 0 < |theta| < 2 pi, tolerance > 0. O(1).
[[nodiscard]] int chord_count(double radius, double theta, double tolerance);

/// The radius (metres) of the arc from `from` to `to` turning by `extent_deg` degrees.
/// @pre from != to, 0 < |extent_deg| < 360. O(1).
[[nodiscard]] double arc_radius(Point2 from, Point2 to, double extent_deg);

/// The centre line of `wall` as the polyline it is built as: {from, to} for a straight wall;
/// for an arc wall (`arc_extent`) the end points of its chord_count equal chords, turning
/// counter-clockwise for a positive extent (the centre to the left of from -> to), first
/// exactly `from` and last exactly `to`. `chord_tolerance` is the site's (or its default).
/// @pre from != to; an arc_extent, when present, with 0 < |arc_extent| < 360.
/// O(chords).
[[nodiscard]] std::vector<Point2> centre_polyline(const Wall& wall, double chord_tolerance);

/// @return the site's chord tolerance, or the format's default (kDefaultChordTolerance).
[[nodiscard]] double chord_tolerance_of(const Site& site);

/// @return the length (metres, in doubles) of the polyline `points`. O(points).
[[nodiscard]] double polyline_length(const std::vector<Point2>& points);

/// @return whether `wall` is an arc that can be built: an arc_extent with
///         0 < |arc_extent| < 360 and from != to, all finite. O(1).
[[nodiscard]] bool is_buildable_arc(const Wall& wall);

/// A plan whose arc walls are their chords, for code written for straight walls (drawings,
/// validation), and where each object came from.
struct ChordPlan {
  Plan plan;
  std::vector<std::size_t> source_wall;     ///< by wall of `plan`: its index in the input
  std::vector<std::size_t> source_opening;  ///< by opening of `plan`: its index in the input
  /// By opening of `plan`: for a piece of an arc wall's opening, the index of its chord in
  /// `plan.walls`; npos for an opening that is not cut.
  std::vector<std::size_t> chord;
};

inline constexpr std::size_t kNoChord = static_cast<std::size_t>(-1);

/// `plan` with each buildable arc wall replaced by its chords (centre_polyline), each keeping
/// the wall's id, fields and its share of a sloped top (heights interpolated along the
/// polyline); the openings of an arc wall cut into one piece per chord their outline's extent
/// (along the polyline and up) crosses, each the rectangle of that extent on its chord, with
/// the opening's id. Everything else is copied. O(walls + chords + openings x chords).
[[nodiscard]] ChordPlan with_arcs_as_chords(const Plan& plan);

}  // namespace roomcad
