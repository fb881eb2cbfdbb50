// SPDX-License-Identifier: GPL-3.0-or-later
// The general path: CGAL's exact Nef polyhedra. A cluster of walls is united (balanced tree),
// the union of all its holes is subtracted in one batch, and the result's facets (maximal
// coplanar regions, every boundary vertex included, so no T-junctions) become faces.
#pragma once

#include <span>

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

/// Builds the solid of a cluster of walls with their holes.
/// @param[in] walls  the cluster: no wall outside it may touch one inside it.
/// @param[in] first_opening_object Model::objects index of opening 0
/// @return faces, rounded to the nearest doubles, classified (classify_face). Faces with
///         holes come triangulated (by CGAL), all triangles of one facet in one colour
///         (unify_facet_labels); others are single polygons. In an order of their own
///         (corners sorted by their exact coordinates), the same in every run.
///         Cost about O(n log n) Nef operations for n walls and holes (seconds for hundreds).
/// @throws PreconditionError if the result is empty while the walls are not.
[[nodiscard]] FaceSoup build_cluster_cgal(std::span<const WallFrame* const> walls,
                                          int first_opening_object);

}  // namespace roomcad::detail
