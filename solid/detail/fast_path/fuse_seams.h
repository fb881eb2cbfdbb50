// SPDX-License-Identifier: GPL-3.0-or-later
// Fewer triangles on the fast path: where two collinear walls meet a stem at a hub, the hub
// has a corner on their common outer side (top and bottom). Every face around that corner
// (both walls' side faces, both walls' tops and the hub's top; likewise at the bottom) ends
// there, so the corner costs a vertex and a triangle per face. Faces that are coplanar and
// alike (kind and colour) are fused across it and the corner, now a straight-through vertex
// of every face using it, is dropped: one face runs along both walls, as CGAL's merged facets do.
#pragma once

#include <span>
#include <vector>

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/fast_path/hubs.h"

namespace roomcad::detail {

/// The corners of `hubs` between two collinear arms (outward directions opposite), at the
/// hub's base and top. @return points in metres, two per such corner. O(corners).
[[nodiscard]] std::vector<OpenMesh::Vec3d> find_seam_points(std::span<const Hub> hubs,
                                                            const std::vector<WallFrame>& frames);

/// Fuses faces across each seam point and drops the point where it is then straight-through
/// in every face that uses it; where it is not (faces of other colours or kinds meet there),
/// the point stays, so the surface stays closed either way.
/// @param[in,out] soups   faces of the fast path (walls and hubs); a fused face replaces the
///                        first of its parts (in soup order), the others are removed.
/// @param[in]     points  seam points (find_seam_points)
/// Cost O(n) expected for n corners (hashing) plus O(p x f) for f faces around each point.
void fuse_seams(std::span<FaceSoup> soups, std::span<const OpenMesh::Vec3d> points);

}  // namespace roomcad::detail
