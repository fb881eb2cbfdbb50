// SPDX-License-Identifier: GPL-3.0-or-later
// What stands between a point and the sun: the triangles of a plan's built solid (walls and
// slabs, openings cut) and of its obstructions' prisms, in an AABB tree that answers "does the
// ray from here towards the sun pass through anything?".
#pragma once

#include <memory>
#include <vector>

#include "mesh/solid_mesh.h"
#include "plan/plan.h"

namespace roomcad {

class SunBlockers {
 public:
  /// @param[in] solid         the wall solid of a built model (Model::walls), closed
  /// @param[in] obstructions  the plan's obstructions (simple outlines, positive heights)
  /// Cost O(t log t) for t triangles.
  SunBlockers(const SolidMesh& solid, const std::vector<Obstruction>& obstructions);
  ~SunBlockers();
  SunBlockers(SunBlockers&&) noexcept;
  SunBlockers& operator=(SunBlockers&&) noexcept;

  /// @return whether the ray from `from` along `direction` meets a triangle anywhere but at
  ///         `from` itself: a triangle whose plane holds `from` (a face the point lies on, or a
  ///         ray along it) never blocks, so a point on a wall's face sees past that face.
  ///         Decided with exact predicates on the doubles given (a ray through an edge of the
  ///         solid, exactly, counts as blocked). Thread-safe. O(log t) typically.
  [[nodiscard]] bool blocks(const Vec3& from, const Vec3& direction) const;

  /// @return the number of triangles held.
  [[nodiscard]] std::size_t size() const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace roomcad
