// SPDX-License-Identifier: GPL-3.0-or-later
// Plans finer than their doubles: a feature under a tenth of a micrometre, or coordinates past
// 10 km.
//
// Why: the general path's solid is exact, and only its corners are rounded to doubles when
// it is written. Where a plan's features are millions of times finer than its coordinates (a
// wall a nanometre thick, a window 2e-8 m high, a home 750 km from its origin), a rounded
// corner can land across a face a few ulps away, and the solid as written crosses itself
// (every fuzzed plan whose solid failed so has such a feature: docs/stress-findings.md).
// build_model checks the written solid of such plans as `build --check` does, and refuses
// it by name if it fails; other plans skip that check, which costs 2 to 8 times the build.
#pragma once

#include <optional>
#include <string>

#include "plan/plan.h"

namespace roomcad::detail {

/// Features finer than this (metres) may round into faces that cross. Every fuzzed plan whose
/// written solid failed had one of 2e-8 m or less; real homes have features down to 3e-7 m
/// (parallel walls drawn 3e-7 m apart), which build well.
inline constexpr double kFinestFeature = 1e-7;
/// Coordinates farther than this from the origin (metres) leave doubles coarser than 2e-12 m.
inline constexpr double kFarthestCoordinate = 1e4;

/// @return the plan's first feature finer than kFinestFeature, named with its size: a dimension
///         (a wall's length, thickness or height, an opening's width or height, a slab's
///         thickness: "wall 'w3' is 1e-09 m thick"), else a step between two heights (bases,
///         tops, sills, heads, slab faces: "the base of wall 'b' (z 1e-09 m) lies 1e-09 m
///         above the base of wall 'a' (z 0 m)"), else two walls, or a wall and an axis, whose
///         directions differ by under kFinestFeature / kFarthestCoordinate radians ("wall 'w'
///         runs 3.9e-14 rad off the y axis"), or two parallel walls on lines closer than
///         kFinestFeature ("wall 'a' runs parallel to wall 'b', 1e-17 m from its line"), or
///         ends of walls along one line closer than that, yet apart ("an end of wall 'b'
///         lies 2.2e-16 m along their line from an end of wall 'a'"); or a corner past
///         kFarthestCoordinate; nothing if there is none. Heights are absolute
///         (levels' elevations added); arc walls count by their dimensions and corners only
///         (their chords' directions and heights, computed, differ by ulps by construction).
///         O(n log n).
[[nodiscard]] std::optional<std::string> fine_feature(const Plan& plan);

}  // namespace roomcad::detail
