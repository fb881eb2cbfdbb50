// SPDX-License-Identifier: GPL-3.0-or-later
// Exact 3D predicates for drawings (CGAL's Epick: filtered, exact on the double inputs), behind
// a plain header so that only exact_3d.cpp includes CGAL.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace roomcad::detail {

using Triangle3 = std::array<glm::dvec3, 3>;

/// @return true if the closed segment [a, b] and the closed triangle meet (touching counts).
///         A degenerate (zero-area) triangle is treated as its segment or point. O(1), exact.
[[nodiscard]] bool segment_meets_triangle(const glm::dvec3& a, const glm::dvec3& b,
                                          const Triangle3& t);

/// Whether the edge p-q, shared by a face with the vertex r0 and a face with the vertex r1
/// (each off the line pq, in its face's plane), is a crease a drawing shows: false when the
/// faces face the same way (`same_facing`: their normals agree, as two pieces of one plane in a
/// consistently oriented mesh do) and the four points are coplanar: exactly, or with the faces
/// less than 1e-9 rad apart (faces of one plane whose corners the modeller rounded to
/// doubles). Faces may be non-convex. A zero-angle fin (facing apart) and a collinear r0 or r1
/// count as creases. O(1); exact unless within the rounding tolerance.
[[nodiscard]] bool is_crease(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r0,
                             const glm::dvec3& r1, bool same_facing);

/// @return true if the triangle is seen edge-on: its plane contains the eye (`perspective`) or
///         the view direction `forward` (orthographic; exact for the direction as given). Such a
///         face covers no area of the picture and hides nothing. O(1), exact.
[[nodiscard]] bool is_edge_on(const Triangle3& t, const glm::dvec3& eye, const glm::dvec3& forward,
                              bool perspective);

/// @return true if r lies exactly on the line through p and q (p != q). O(1), exact.
[[nodiscard]] bool is_collinear(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r);

}  // namespace roomcad::detail
