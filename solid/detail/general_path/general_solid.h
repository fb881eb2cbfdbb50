// SPDX-License-Identifier: GPL-3.0-or-later
// The general path: the exact solid of any cluster of walls without 3D booleans.
//
// The solid R is the union of the solids (wall pieces) minus the union of the holes, every
// one a convex polyhedron (convex_pieces.h). Every face of R lies on a plane carrying a face of
// some primitive, so R's faces are found plane by plane: on a plane, the region where R is
// just below and not just above is a face looking along the plane's normal, and the other
// way round; both are exact 2D booleans of the primitives' sections and faces in that plane
// (plane_faces.h). On a plane whose polygons are rectangles along its axes, but for a few with
// slanted edges (walls drawn along x and y), the grid of their lines decides the same regions
// (grid_faces.h); a face that no other polygon of its plane overlaps is a face as it is
// (lone_faces.h). Every vertex is then where three planes meet (or input doubles), so faces of
// different planes share their vertices exactly; a vertex inside another face's edge is
// inserted there (face_stitching.h), and each vertex is rounded to doubles once.
//
// Exactness: every decision is the sign of a polynomial in the plan's doubles, evaluated
// exactly (exact_planes.h), so the faces found are R's, exactly; the only approximation is
// the final rounding of each vertex to the nearest doubles, as on the Nef path (whose corners
// round the same way): points that round to within a few ulps of each other are then snapped
// together (snap_soup.h). Planes are independent, so they are built in parallel; the output
// does not depend on the thread count.
#pragma once

#include <span>

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/frames/slab_frames.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

/// Builds the solid of a cluster of walls with their holes, and slabs.
/// @param[in] walls  the cluster: no wall or slab outside it may touch one inside it.
/// @param[in] slabs  the cluster's slabs (the holes cut them too where they meet)
/// @param[in] first_opening_object Model::objects index of opening 0
/// @param[in] first_slab_object    Model::objects index of slab 0 (SlabFrame::slab)
/// @param[in] grid_planes  the planes of rectangles on their grid (grid_faces.h); false: every
///                         plane through its 2D boolean
/// @return faces, rounded to the nearest doubles, each labelled by the primitive it belongs
///         to (a wall's top, side, end or bottom; an opening's jamb, sill or lintel). Cost
///         about O(p log p) predicates for p primitive faces near each other, plus exact
///         arithmetic where shapes touch.
/// @throws PreconditionError (not_buildable) naming the walls if the solid touches itself
///         along an edge (it would not be 2-manifold) or is unbounded.
[[nodiscard]] FaceSoup build_cluster_general(std::span<const WallFrame* const> walls,
                                             std::span<const SlabFrame* const> slabs,
                                             int first_opening_object, int first_slab_object,
                                             bool grid_planes);

}  // namespace roomcad::detail
