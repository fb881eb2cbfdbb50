// SPDX-License-Identifier: GPL-3.0-or-later
// The verdict of `roomcad build --check` (and the Python Model.check): the wall solid as
// written checked as a solid (modeling/mesh_check.h), and its volume against the volume
// computed from the plan alone.
#pragma once

#include "modeling/mesh_check.h"
#include "modeling/plan.h"
#include "modeling/solid_mesh.h"

namespace roomcad {

/// The largest relative difference between the solid's volume and the analytic one that passes.
inline constexpr double kWallVolumeTolerance = 1e-9;

struct WallCheck {
  SolidCheck solid;
  double analytic = 0.0;  ///< analytic_wall_volume(plan), cubic metres
  double relative = 0.0;  ///< |volume - analytic| / analytic
  bool ok = false;        ///< a valid solid within kWallVolumeTolerance
};

/// Checks `model.walls`, built from `plan`. Cost: check_solid plus analytic_wall_volume.
/// @throws PreconditionError as analytic_wall_volume for a plan that cannot be built.
[[nodiscard]] WallCheck check_walls(const Model& model, const Plan& plan);

}  // namespace roomcad
