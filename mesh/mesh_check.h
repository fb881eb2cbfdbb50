// SPDX-License-Identifier: GPL-3.0-or-later
// Checks of a solid as written (its doubles), and its volume computed from the plan alone,
// for `roomcad build --check` and the tests.
#pragma once

#include <cstddef>

#include "mesh/solid_mesh.h"
#include "plan/plan.h"

namespace roomcad {

/// What check_solid found. A solid passes when is_valid() holds.
struct SolidCheck {
  std::size_t vertices = 0;
  std::size_t faces = 0;         ///< polygons
  std::size_t triangles = 0;     ///< after triangulating each polygon (triangulate_face)
  std::size_t border_edges = 0;  ///< 0 when closed
  std::size_t non_manifold_vertices = 0;
  std::size_t rejected_triangles = 0;    ///< triangles that would make an edge non-manifold
  std::size_t degenerate_triangles = 0;  ///< collinear corners (exact predicate)
  std::size_t self_intersections = 0;    ///< pairs of intersecting triangles (exact predicates)
  /// Pairs of triangles that meet only at points both hold, each written as its own vertex:
  /// where the solid touches itself at a point or along an edge (walls meeting at a corner
  /// only, a slab's corner on a wall's edge), a copy of the vertex per side keeps the mesh
  /// 2-manifold. Not an intersection: the faces do not cross.
  std::size_t touching_pairs = 0;
  std::size_t inward_components = 0;  ///< components facing the wrong way (inside out)
  std::size_t cavities = 0;  ///< components bounding a void inside the solid (facing in, rightly)
  std::size_t components = 0;
  long genus = 0;       ///< sum over components of (2 - Euler characteristic) / 2
  double volume = 0.0;  ///< cubic metres

  [[nodiscard]] bool is_closed() const { return border_edges == 0; }
  [[nodiscard]] bool is_manifold() const {
    return non_manifold_vertices == 0 && rejected_triangles == 0;
  }
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

}  // namespace roomcad
