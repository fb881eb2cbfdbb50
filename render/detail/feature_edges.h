// SPDX-License-Identifier: GPL-3.0-or-later
// The edges a line drawing shows and the triangles that can hide them, taken from the model's
// polygon meshes in double precision.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "mesh/solid_mesh.h"
#include "render/detail/exact_3d.h"

namespace roomcad::detail {

struct Edge3 {
  glm::dvec3 a{0.0};
  glm::dvec3 b{0.0};
};

/// Appends the feature edges of a mesh: boundary edges and edges between two faces that are
/// not one plane (exact: detail::is_crease). Edges between coplanar faces (tiles of the floor,
/// faces split by a neighbour's vertex) and triangulation diagonals never appear: the mesh's
/// polygons are not triangulated. Deleted and zero-length edges are skipped.
/// @param[in,out] out  appended to, in edge order (deterministic). O(edges * face size).
void append_feature_edges(const SolidMesh& mesh, std::vector<Edge3>& out);

/// Appends the triangles of every face of a mesh (modeling's triangulate_face), in face order.
/// Faces of zero area add nothing. O(sum of face size^2).
void append_triangles(const SolidMesh& mesh, std::vector<Triangle3>& out);

}  // namespace roomcad::detail
