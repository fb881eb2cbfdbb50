// SPDX-License-Identifier: GPL-3.0-or-later
// Sweet Home 3D cut-out shapes (`doorOrWindow` `cutOutShape`: an SVG path in the item's unit
// square, y down) as polygons, and the polygon clipping that fits them to one wall.
#pragma once

#include <optional>
#include <string_view>

#include "plan/plan.h"

namespace roomcad::sh3d {

/// The outline of an SVG path (commands M, L, H, V, A, C, Q, Z, absolute and relative; its
/// first closed sub-path) in the unit square with y turned up (v = 1 - y), counter-clockwise.
/// Arcs and curves become chords no farther than `tolerance` metres from the curve, for an
/// item `width` x `height` metres.
/// @return the polygon, or nullopt for a path that does not parse or encloses no area.
/// O(path length + chords).
[[nodiscard]] std::optional<Polygon> parse_cut_out(std::string_view path, double width,
                                                   double height, double tolerance);

/// `polygon` clipped to the half-plane where a * x + b * y <= c (Sutherland-Hodgman; the
/// polygon may be any simple polygon, the result is its part on that side, possibly with
/// zero-width bridges, which a convex clip of a convex or star-shaped outline never has).
/// O(corners).
[[nodiscard]] Polygon clip_half_plane(const Polygon& polygon, double a, double b, double c);

}  // namespace roomcad::sh3d
