// SPDX-License-Identifier: GPL-3.0-or-later
// The verdict of `roomcad build --check` (and the Python Model.check): the wall solid as
// written checked as a solid (mesh/mesh_check.h), and its volume against the volume
// computed from the plan alone.
#pragma once

#include <string>

#include "mesh/mesh_check.h"
#include "mesh/solid_mesh.h"
#include "plan/plan.h"

namespace roomcad {

/// The largest relative difference between the solid's volume and the analytic one that
/// passes, beside what rounding the solid's vertices to doubles allows (volume_tolerance).
inline constexpr double kWallVolumeTolerance = 1e-9;

/// How far a mesh written in doubles can be from the exact solid it stands for: one ulp of its
/// largest coordinate (each vertex is off by at most half an ulp in each of x, y, z). Near the
/// origin this is ~1e-15 m; at 1e7 m it is 1.9e-9 m, which on walls 1e-4 m thick is 2e-5 of
/// the volume: no output in doubles can do better there. O(vertices).
[[nodiscard]] double vertex_rounding(const SolidMesh& mesh);

/// The volume difference the mesh's doubles allow, cubic metres: kWallVolumeTolerance times
/// `volume`, plus its surface area times vertex_rounding (moving every vertex by d changes the
/// volume by at most area x d; it matters only for features a few million ulps thin, such as
/// a wall a nanometre thick). O(vertices).
[[nodiscard]] double volume_tolerance(const SolidMesh& mesh, double volume);

struct WallCheck {
  SolidCheck solid;
  double analytic = 0.0;  ///< analytic_wall_volume(plan), cubic metres
  double relative = 0.0;  ///< |volume - analytic| / analytic
  double limit = 0.0;     ///< volume_tolerance(walls, analytic), cubic metres
  bool ok = false;        ///< a valid solid, |volume - analytic| within limit
};

/// Checks `model.walls`, built from `plan` (without its slabs where the model was built
/// without them, Model::slabs_built). Cost: check_solid plus analytic_wall_volume.
/// @throws PreconditionError as analytic_wall_volume for a plan that cannot be built.
[[nodiscard]] WallCheck check_walls(const Model& model, const Plan& plan);

/// @return what failed, in words ("open edges: 2, self-intersections: 3"); empty if nothing
///         did. O(1).
[[nodiscard]] std::string describe_failures(const WallCheck& check);

}  // namespace roomcad
