// SPDX-License-Identifier: GPL-3.0-or-later
// Checks of a solid as written (its doubles), and its volume computed from the plan alone,
// for `roomcad build --check` and the tests.
#pragma once

#include <cstddef>

#include "modeling/plan.h"
#include "modeling/solid_mesh.h"

namespace roomcad {

/// What check_solid found. A solid passes when is_valid() holds.
struct SolidCheck {
  std::size_t vertices = 0;
  std::size_t faces = 0;       ///< polygons
  std::size_t triangles = 0;   ///< after triangulating each polygon (triangulate_face)
  std::size_t border_edges = 0;          ///< 0 when closed
  std::size_t non_manifold_vertices = 0;
  std::size_t rejected_triangles = 0;    ///< triangles that would make an edge non-manifold
  std::size_t degenerate_triangles = 0;  ///< collinear corners (exact predicate)
  std::size_t self_intersections = 0;    ///< pairs of intersecting triangles (exact predicates)
  /// Pairs of triangles that meet only at points both hold, each written as its own vertex:
  /// where the solid touches itself at a point or along an edge (walls meeting at a corner
  /// only, a slab's corner on a wall's edge), a copy of the vertex per side keeps the mesh
  /// 2-manifold. Not an intersection: the faces do not cross.
  std::size_t touching_pairs = 0;
  std::size_t inward_components = 0;     ///< components facing the wrong way (inside out)
  std::size_t cavities = 0;              ///< components bounding a void inside the solid (facing in, rightly)
  std::size_t components = 0;
  long genus = 0;       ///< sum over components of (2 - Euler characteristic) / 2
  double volume = 0.0;  ///< cubic metres

  [[nodiscard]] bool is_closed() const { return border_edges == 0; }
  [[nodiscard]] bool is_manifold() const { return non_manifold_vertices == 0 && rejected_triangles == 0; }
  [[nodiscard]] bool is_valid() const {
    return is_closed() && is_manifold() && degenerate_triangles == 0 && self_intersections == 0 &&
           inward_components == 0;
  }
};

/// Checks a solid exactly as its doubles are: each face is triangulated (triangulate_face),
/// and CGAL's exact predicates decide degeneracy and self-intersection.
/// @param[in] mesh  planar polygon faces (a SolidMesh with face normals)
/// @return the findings; the volume is summed relative to a point of the mesh, so a solid far
///         from the origin keeps its precision. O(n log n) in triangles.
[[nodiscard]] SolidCheck check_solid(const SolidMesh& mesh);

/// The volume of the plan's solid from the plan alone, independent of the builders' planes:
/// (union of walls and slabs) minus (union of holes), walls with sloped tops, holes rectangular
/// or shaped (the opening's outline through the wall), slabs their outline minus their holes.
/// Over z the cross-section's area is a polynomial of degree <= 2 between events: every
/// primitive's corner heights, and the heights where a tilted plane (a sloped top, an edge of
/// a shaped hole) meets two other face planes within their boxes. Each interval takes one
/// exact area (CGAL 2D boolean operations on Epeck) where nothing moves, else Simpson's rule
/// on three. The work is split into small groups: the flat walls and slabs together (as
/// before: one area per interval), each sloped wall against what is near it, each cluster of
/// overlapping holes against the walls and slabs near it.
/// @pre the plan builds (build_model does not throw).
/// @return cubic metres, the exact sum rounded once. O(s n log n) for s intervals of the flat
///         walls and slabs and n of them, plus small groups per sloped wall and hole cluster
///         (candidate triples of planes filtered by boxes).
/// @throws PreconditionError as build_model does for walls and openings that cannot be built.
[[nodiscard]] double analytic_wall_volume(const Plan& plan);

}  // namespace roomcad
