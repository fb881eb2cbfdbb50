// SPDX-License-Identifier: GPL-3.0-or-later
// Triangles of a mesh with its corners rounded to float32, for the formats that store float32
// (binary STL): no triangle is flat after rounding, and the rounded surface stays closed.
//
// Why it is needed: the model's doubles hold features narrower than a float step (a sliver a
// few nanometres wide where two walls meet at a slant; a float step is about 1e-6 m at 10 m).
// Rounded to float32, two corners of such a face become one point, or three corners fall on
// one line; ear clipping the doubles then writes triangles with a repeated corner or zero area.
#pragma once

#include <array>
#include <vector>

#include "mesh/solid_mesh.h"

namespace roomcad {

/// One triangle of a float32 triangulation.
struct FloatTriangle {
  std::array<OpenMesh::Vec3f, 3> corners;  ///< metres, float32; counter-clockwise seen from outside
  SolidMesh::FaceHandle face;              ///< the polygon face it comes from (for its normal)
};

/// Triangulates every face of `mesh` after rounding each vertex to the nearest float32 (-0 as
/// +0), the way an STL file stores it and an STL reader welds it (equal coordinates, one vertex):
///  1. each face's ring of rounded corners loses consecutive repeats and spikes (a corner the
///     ring runs to and straight back from, where rounding closed a sliver of the face) and is
///     ear-clipped on the rounded coordinates (triangulate_face), so it keeps positive area
///     wherever the rounded polygon has any;
///  2. the triangles still flat after that (repeated corner, or three corners on one line: a
///     sliver face, or the zero-area part of a face that rounding pinched) are dropped, and every
///     corner of a collinear one is inserted into the triangle edges it lies strictly inside
///     (those triangles are re-triangulated with the point as a straight vertex), so the edges
///     the dropped triangle shared stay shared.
/// @param[in] mesh  polygon faces with face normals (a SolidMesh), metres
/// @return the triangles, face by face in mesh order (re-triangulated ones in place); none has a
///         repeated corner or collinear corners (CGAL exact predicates on the floats). Every
///         directed edge between two rounded points is used as often as its reverse whenever that
///         holds for the mesh (a closed mesh stays closed). An empty mesh gives none.
///         Cost O(n log n + t q) for n vertices, t triangles, q corners of flat triangles.
[[nodiscard]] std::vector<FloatTriangle> triangulate_in_float(const SolidMesh& mesh);

}  // namespace roomcad
