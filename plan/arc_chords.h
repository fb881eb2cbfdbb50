// SPDX-License-Identifier: GPL-3.0-or-later
// Arc walls (plan format version 2, `arc_extent`) as the chord polylines they are built,
// checked and measured as (docs/plan-format.md "Version 2"): n equal chords, n the smallest
// count whose sagitta R (1 - cos(theta / 2n)) is at most the site's chord tolerance.
#pragma once

#include <cstddef>
#include <vector>

#include "plan/plan.h"

namespace roomcad {

/// At most this many chords per arc: a tolerance that asks for more is refused (too_large).
inline constexpr std::size_t kMaxChords = 4096;

/// @return the site's chord tolerance (kDefaultChordTolerance when the file gives none).
[[nodiscard]] double chord_tolerance_of(const Site& site);

/// The number of chords of an arc of `extent_deg` degrees over a chord `span` metres long.
/// @pre 0 < |extent_deg| < 360, span > 0 and tolerance > 0, all finite.
/// @return n >= 1, or kMaxChords + 1 when more than kMaxChords are needed. O(1).
[[nodiscard]] std::size_t chord_count(double span, double extent_deg, double tolerance);

/// The wall's centre line as built: {from, to} for a straight wall, else the n + 1 corners
/// of its chords, the first exactly `from` and the last exactly `to` (the inner ones rounded
/// to doubles). @throws PreconditionError (too_large) naming the wall past kMaxChords, and
/// (not_buildable) for an extent outside (-360, 360) or 0, or a zero-length arc. O(n).
[[nodiscard]] std::vector<Point2> chord_polyline(const Wall& wall, double chord_tolerance);

}  // namespace roomcad
