// SPDX-License-Identifier: GPL-3.0-or-later
// What a face of a boolean result is (wall side, top, jamb, ...) and which object owns it,
// found from its plane and position against the walls and holes that made it.
#pragma once

#include <span>

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

struct FaceLabel {
  FaceKind kind = FaceKind::wall_face;
  int object = -1;
  Color color;
};

/// @return the kind of a face of wall `frame` with outward normal `n` (unit): top, bottom, side
///         (normal across the wall) or end. O(1).
[[nodiscard]] FaceKind wall_face_kind(const WallFrame& frame, const OpenMesh::Vec3d& n);

/// Labels a face of the solid of `walls`.
/// @param[in] points  the face's corners (rounded), counter-clockwise from outside
/// @param[in] walls   the walls (and their holes) the face came from
/// @param[in] first_opening_object Model::objects index of opening 0
/// @return a face lying in a hole's box is that opening's sill, lintel or jamb; any other is
///         the top, bottom, side or end of the wall holding most of its corners.
///         Cost O(points x (walls + holes)). Tolerance 1e-6 m + 1e-12 x |coordinates|: labels
///         are descriptive, no verdict depends on them.
[[nodiscard]] FaceLabel classify_face(std::span<const OpenMesh::Vec3d> points,
                                      std::span<const WallFrame* const> walls,
                                      int first_opening_object);

}  // namespace roomcad::detail
