// SPDX-License-Identifier: GPL-3.0-or-later
// Faces that need no 2D boolean: on a plane of the general path (general_solid.h), a primitive's
// face whose interior no other polygon of the plane meets is a face of the solid as it is.
//
// Why: a plane's 2D boolean (plane_faces.h) or grid (grid_faces.h) costs tens of microseconds
// even for a polygon or two, and most planes of a home drawn with arcs hold only such faces:
// each chord of an arc has its own side planes, which the neighbouring chords cross only beyond
// the mitre they share, and a storey's tops and bottoms of mitred chords touch only along their
// mitres. Touching polygons do not change the regions either side of the solid's boundary, so
// what the boolean would decide for a lone face is the face itself; the only difference is the
// points where others touch its edges, which stitching inserts (face_stitching.h).
#pragma once

#include <optional>
#include <vector>

#include "solid/detail/general_path/plane_faces.h"

namespace roomcad::detail {

/// @return whether the interiors of two convex polygons of one plane meet: exactly, no line
///         of either polygon has all the other's vertices on its closed outer side (two convex
///         polygons whose interiors are apart have a separating line through an edge of one).
///         O(n m) predicates.
[[nodiscard]] bool interiors_meet(const PlaneSet& set, const PlanePolygon& a,
                                  const PlanePolygon& b);

/// @return the solid's faces when no two contributions' interiors meet (take_lone_faces would
///         take them all), else nothing, as soon as two are found that meet. Cost as below, or
///         less.
[[nodiscard]] std::optional<std::vector<SolidFace>> faces_if_apart(
    const PlaneSet& set, PlaneRef plane, const std::vector<Contribution>& contributions);

/// Takes out of `contributions` every one whose interior meets no other's.
/// @param[in]     plane          the plane the contributions lie in (sign +1)
/// @param[in,out] contributions  on return, only those that meet another
/// @return the solid's faces among those taken: each solid primitive's face (a section, or a
///         hole's face alone, is no face of the solid), outward and counter-clockwise seen from
///         outside, its vertices rounded. O(n log n) box tests plus interiors_meet where boxes
///         meet.
[[nodiscard]] std::vector<SolidFace> take_lone_faces(const PlaneSet& set, PlaneRef plane,
                                                     std::vector<Contribution>& contributions);

}  // namespace roomcad::detail
