// SPDX-License-Identifier: GPL-3.0-or-later
// Building the 3D model of a plan: the wall solid (walls joined, openings cut), the tiled
// floor and the fixtures, as OpenMesh meshes (mesh/solid_mesh.h).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "core/error.h"
#include "mesh/parts.h"
#include "mesh/solid_mesh.h"
#include "plan/plan.h"

namespace roomcad {

enum class BooleanPath {
  automatic,  ///< per wall: the exact fast path where no boolean is needed, else the general path
  general,  ///< the exact general path (plane by plane, solid/detail/general_path/general_solid.h)
            ///< for every wall
  nef,      ///< CGAL's exact Nef polyhedra for every wall: the reference, to compare against
  fast_then_nef,  ///< the fast path where it applies, Nef polyhedra for the rest: the automatic
                  ///< build before the general path, kept for benchmarks
};

/// @return whether clusters of this path go through Nef polyhedra.
[[nodiscard]] inline bool uses_nef(BooleanPath path) {
  return path == BooleanPath::nef || path == BooleanPath::fast_then_nef;
}

struct BuildOptions {
  BooleanPath boolean = BooleanPath::automatic;
  Parts parts{};
  int threads = 0;  ///< 0: all cores; output is identical at any thread count
  /// The general path's planes whose polygons are rectangles along their axes, nearly all
  /// (walls drawn along x and y), built on the grid of their lines
  /// (solid/detail/general_path/grid_faces.h); false: every plane through the general 2D boolean
  /// (but for the faces no other polygon of their plane meets:
  /// solid/detail/general_path/lone_faces.h), the reference for tests and benchmarks.
  bool grid_planes = true;
  /// Also find the model's cells and portals (Model::cells), for renderers that draw only
  /// what the camera's room lets through. Needs the walls part.
  bool cells = false;
};

/// What a build did, for --stats, benchmarks and tests.
struct BuildStats {
  std::size_t fast_path_walls = 0;
  std::size_t general_path_walls = 0;
  std::size_t nef_path_walls = 0;
  double build_ms = 0.0;
};

/// @return the object table of the plan's model (Model::objects): the wall ids in plan order,
///         then the opening ids. O(n).
[[nodiscard]] std::vector<std::string> model_object_ids(const Plan& plan);

/// Builds the model of a plan.
/// @pre validate(plan).ok() (validation/validate.h); a plan with errors may still be built
///      (`--force`), but an opening that cannot be cut throws instead of leaving a wall whole.
/// @throws PreconditionError naming the object that could not be built. Never a silent
///         missing hole.
[[nodiscard]] Model build_model(const Plan& plan, const BuildOptions& options = {},
                                BuildStats* stats = nullptr);

/// The cells and portals of the model build_model makes of `plan` with these parts
/// (Model::cells; empty without walls), found alone: for a window that builds its model in
/// pieces. @throws PreconditionError as build_model, for a wall it cannot build.
/// Cost: see solid/detail/cells/find_cells.h.
[[nodiscard]] Cells find_model_cells(const Plan& plan, const Parts& parts = {});

}  // namespace roomcad
