// SPDX-License-Identifier: GPL-3.0-or-later
// Triangulation of one planar polygon face, for everything that needs triangles (STL export,
// mesh checks, the rasteriser) while the model itself keeps few, large polygons.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <OpenMesh/Core/Geometry/VectorT.hh>

namespace roomcad {

/// Triangulates a simple planar polygon by ear clipping with exact orientation predicates.
/// @param[in] points  the polygon's vertices in order (either orientation); planar and simple
///                    (no self-crossing), possibly with straight (collinear) vertices, which is
///                    how faces carry the vertices of their neighbours (no T-junctions).
/// @param[in] normal  any normal of the polygon's plane (need not be unit length); used only to
///                    pick the projection plane.
/// @return points.size() - 2 triangles as index triples into `points`, each with the polygon's
///         own orientation and positive area; empty if fewer than 3 points or zero area.
///         Cost O(n^2) for n points.
/// Degenerate input: a non-simple polygon still gets n - 2 triangles (the largest remaining
/// ear is clipped when no clean one exists), never an endless loop.
[[nodiscard]] std::vector<std::array<int, 3>> triangulate_face(
    std::span<const OpenMesh::Vec3d> points, const OpenMesh::Vec3d& normal);

}  // namespace roomcad
