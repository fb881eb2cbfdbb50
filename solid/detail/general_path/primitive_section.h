// SPDX-License-Identifier: GPL-3.0-or-later
// The section of a convex primitive (convex_pieces.h) by a plane crossing it: the convex
// polygon where the plane cuts it, which the general path puts into that plane's 2D boolean.
//
// Where no vertex of the primitive lies on the plane, each face the plane crosses has exactly
// one edge where it passes from the plane's positive side to its negative one and one back
// (it is convex); the section runs along the crossing faces, each to the edge it shares with
// the next, so it is made from its own corners alone: one point per crossing edge. Where a
// vertex lies on the plane (or a face's edge lies on a plane no face of the primitive has),
// the section is clipped from the box's square in the plane by every face instead, which
// makes and drops points along the way: about three times the predicates.
#pragma once

#include <optional>

#include "solid/detail/general_path/convex_pieces.h"

namespace roomcad::detail {

/// The section from the faces the plane crosses. @return none where a vertex of the primitive
///         lies on the plane, the faces do not close into one loop, or fewer than three cross
///         it (then section_of clips). O(v) predicates, O(c) points made.
[[nodiscard]] std::optional<PlanePolygon> section_from_crossings(const PlaneSet& set,
                                                                 const Primitive& primitive,
                                                                 PlaneRef plane);

/// The section as the box's square in the plane clipped by every face of the primitive.
/// @return none if it has no area. O(f v) predicates for f faces of v corners.
[[nodiscard]] std::optional<PlanePolygon> section_by_clipping(const PlaneSet& set,
                                                              const BoxPlanes& box,
                                                              const Primitive& primitive,
                                                              PlaneRef plane);

/// @param[in] plane  a plane with vertices of `primitive` strictly on both of its sides
/// @return the section: lines on the primitive's faces (outward), counter-clockwise seen from
///         the plane's positive side; none if it has no area. O(v) predicates and O(c)
///         points made for the v corners of the primitive's faces and the c corners of the
///         section (O(f v) predicates where clipped, for f faces).
[[nodiscard]] std::optional<PlanePolygon> section_of(const PlaneSet& set, const BoxPlanes& box,
                                                     const Primitive& primitive, PlaneRef plane);

}  // namespace roomcad::detail
