// SPDX-License-Identifier: GPL-3.0-or-later
// Faces as loose polygons ("a soup") before they become one OpenMesh mesh: what each builder
// (fast path, CGAL path, floor, fixtures) returns, so that builders run in parallel and the
// mesh is assembled once, in plan order, whatever the thread count.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/solid_mesh.h"

namespace roomcad::detail {

/// One planar polygon, counter-clockwise seen from outside, with its face properties.
struct SoupFace {
  std::vector<OpenMesh::Vec3d> points;  ///< metres
  FaceKind kind = FaceKind::wall_face;
  int object = -1;  ///< index into Model::objects, -1 for none
  Color color;
  /// Per point, which copy of it this face uses (empty: copy 0 everywhere). Where a solid
  /// touches itself at a point, the faces around it form separate fans, and each fan gets
  /// its own copy of the vertex so that the mesh stays 2-manifold.
  std::vector<std::uint32_t> copies;
  /// Optional: per point, its vertex's number within this face's soup (equal numbers are one
  /// vertex; a point's copies have different ones). Assembly then looks each vertex up by its
  /// coordinates once, not at every corner. Empty: looked up at every corner.
  std::vector<std::uint32_t> vertices;
};
using FaceSoup = std::vector<SoupFace>;

/// Builds one mesh from soups, in order. Points with bit-identical coordinates become one
/// vertex, which is how neighbouring faces (and a mitre's two walls) are stitched.
/// @param[in] soups    faces; every vertex on a face's edge must be a vertex of that face.
/// @param[in] objects  object ids, for error messages.
/// @param[in] share    whether soups share vertices with each other (false: each soup is a
///                     separate piece, e.g. fixtures that may touch).
/// @return the mesh with rc: face properties and face normals. O(n) expected in points.
/// @throws PreconditionError naming the object, the place and the reason if a face cannot
///         join the mesh: it repeats a corner, one of its edges already has a face on that
///         side (naming that face's object), or a corner has no free gap (complex vertex).
///         Checked before OpenMesh's add_face, which would assert on some of these.
[[nodiscard]] SolidMesh assemble_mesh(std::span<const FaceSoup> soups,
                                      const std::vector<std::string>& objects, bool share = true);

/// Refuses a solid that is not closed, naming where: its corners are the exact solid's
/// rounded to doubles, and where walls meet in features finer than that rounding (a wall an
/// ulp long at a corner of two walls drawn over each other), faces can lose their partners.
/// @param[in] mesh     an assembled solid (assemble_mesh)
/// @param[in] objects  object ids, for the message
/// @throws PreconditionError (not_buildable) naming the objects of the faces beside its open
///         edges and the first such edge. O(n) in halfedges.
void require_closed(const SolidMesh& mesh, const std::vector<std::string>& objects);

/// The vertices of an indexed polygon soup's corners, per corner (polygons in order).
struct FanSplit {
  std::vector<std::uint32_t> copy;        ///< which copy of its point the corner uses
  std::vector<std::uint32_t> vertex;      ///< its vertex: numbered in order of first corner
  std::vector<std::size_t> first_corner;  ///< per polygon, where its corners start (and the end)
};

/// Splits the vertices of an indexed polygon soup into fans: corners around a vertex that
/// are linked through shared edges use one copy of it, separate fans separate copies. Where
/// more than two faces share an edge (solids touching along it), each face is linked with the
/// one across the material from it, so each pair takes its own copies of the edge's ends.
/// @param[in] polygons  vertex indices, each polygon counter-clockwise from outside
/// @param[in] points    their positions (the faces' angles about a shared edge)
/// @param[out] bad_edge on failure, the two vertices of an edge whose faces cannot be paired
///                      (clashing orientations, or pairs whose fans join elsewhere)
/// @return per corner its copy and vertex; empty on failure. O(corners) expected, and
///         O(k log k) more per edge of k > 2 faces.
[[nodiscard]] FanSplit split_fans(const std::vector<std::vector<std::size_t>>& polygons,
                                  const std::vector<OpenMesh::Vec3d>& points,
                                  std::pair<std::size_t, std::size_t>& bad_edge);

/// Gives a face the corners of polygon k of an indexed soup: their points, copies and
/// vertices (split_fans' `fans` of that soup). O(corners).
void set_corners(SoupFace& face, const std::vector<std::vector<std::size_t>>& polygons,
                 std::size_t k, const std::vector<OpenMesh::Vec3d>& points, const FanSplit& fans);

/// @return the Newell normal of a polygon (length = twice its area). O(n).
[[nodiscard]] OpenMesh::Vec3d polygon_normal(std::span<const OpenMesh::Vec3d> points);

}  // namespace roomcad::detail
