// SPDX-License-Identifier: GPL-3.0-or-later
// Stitching the general path's faces into one surface: faces from different planes meet
// along shared lines, and where a vertex of one lies inside an edge of another (a
// T-junction), it is inserted into that edge, exactly: the vertex lies on the edge's plane
// and line (sign 0 of both predicates) strictly between its ends. Then every vertex is
// rounded once to the nearest doubles; equal exact points round to equal doubles, which is
// how the faces share vertices in the mesh (the faces come rounded: plane_faces.h).
#pragma once

#include <cstddef>
#include <vector>

#include "modeling/detail/exact_planes.h"
#include "modeling/detail/snap_soup.h"

namespace roomcad::detail {

/// A face of the solid: a simple polygon on `plane` (oriented outward).
struct SolidFace {
  PlaneRef plane;
  std::size_t owner = 0;         ///< the primitive whose face it is
  std::vector<XPoint> vertices;  ///< counter-clockwise seen from outside
  std::vector<PlaneRef> lines;   ///< lines[k]: the line of edge vertices[k] -> vertices[k + 1]
  std::vector<std::array<double, 3>> rounded;  ///< each vertex rounded to the nearest doubles
};

/// @return the faces as rounded polygons with every vertex lying on an edge inserted into it;
///         tags[k] is the index of the face polygon k came from; is_exact tells, when asked,
///         whether a rounded point is its exact point (an exact test: snap_soup asks it only of
///         points that snap). O(e c) for e edges and c vertices near each (a uniform grid),
///         exact tests only for vertices within a few ulps of an edge; faces in parallel.
[[nodiscard]] IndexedSoup stitch_faces(const PlaneSet& set, const std::vector<SolidFace>& faces);

}  // namespace roomcad::detail
