// SPDX-License-Identifier: GPL-3.0-or-later
// How far apart two built solids are: the symmetric Hausdorff distance between their
// surfaces (CGAL's bounded-error algorithm), which the repair guarantees bound.
#pragma once

#include "mesh/solid_mesh.h"
#include "plan/plan.h"

namespace roomcad::test {

/// @return the symmetric Hausdorff distance between the surfaces of `a` and `b`, in metres, as
///         measured at their corners and on a grid of `spacing` over their edges and faces
///         (CGAL::Polygon_mesh_processing::sample_triangle_mesh, max_distance_to_triangle_mesh):
///         what a move of a face, an edge or a corner shows. O(samples log triangles).
[[nodiscard]] double surface_distance(const SolidMesh& a, const SolidMesh& b, double spacing);

/// @return the plan's wall solid with its slabs, as `roomcad build --parts walls,slabs`
///         builds it (with --force: errors do not stop it). @throws as build_model.
[[nodiscard]] SolidMesh walls_and_slabs(const Plan& plan);

}  // namespace roomcad::test
