// SPDX-License-Identifier: GPL-3.0-or-later
// Stitching the general path's faces into one surface: faces from different planes meet
// along shared lines, and where a vertex of one lies inside an edge of another (a
// T-junction), it is inserted into that edge, exactly: the vertex lies on the edge's plane
// and line (sign 0 of both predicates) strictly between its ends. Then every vertex is
// rounded once to the nearest doubles; equal exact points round to equal doubles, which is
// how the faces share vertices in the mesh (the faces come rounded: plane_faces.h).
#pragma once

#include <cstddef>
#include <span>

#include "solid/detail/assembly/snap_soup.h"
#include "solid/detail/general_path/exact_planes.h"
#include "solid/detail/general_path/plane_faces.h"

namespace roomcad::detail {

/// @return the faces as rounded polygons with every vertex lying on an edge inserted into it;
///         tags[k] is the index of the face polygon k came from; is_exact tells, when asked,
///         whether a rounded point is its exact point (an exact test: snap_soup asks it only of
///         points that snap). O(e log c) for e edges along the axes and c points on their
///         lines (each line's points in order), O(e c) for the other edges and c points in the
///         cells of a uniform grid they cross; exact tests only for points within a few ulps
///         of an edge; faces in parallel.
[[nodiscard]] IndexedSoup stitch_faces(const PlaneSet& set,
                                       std::span<const SolidFace* const> faces);

}  // namespace roomcad::detail
