// SPDX-License-Identifier: GPL-3.0-or-later
// The plan the builders work on (build_model, analytic_wall_volume): version 2 resolved into
// what version 1's machinery builds. Levels are resolved (plan_levels.h: every base
// absolute), and an arc wall becomes one straight wall per chord (arc_chords.h), consecutive
// chords sharing their corners exactly, so they mitre as any two walls meeting end to end;
// an opening in an arc wall becomes one piece per chord it spans, pieces meeting on the
// chords' mitre planes. Faces are labelled back to the plan's own walls and openings.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "plan/plan.h"
#include "solid/detail/assembly/face_soup.h"

namespace roomcad::detail {

struct BuildablePlan {
  Plan plan;                            ///< levels resolved, arcs as chords
  std::vector<std::size_t> wall_of;     ///< per wall of `plan`, the index of the input's wall
  std::vector<std::size_t> opening_of;  ///< per opening of `plan`, the index of the input's
  /// Per opening of `plan`: whether it runs on through the mitre at its chord's from / to end
  /// (make_wall_frames' through_mitre).
  std::vector<std::array<bool, 2>> through_mitre;
  std::size_t input_walls = 0;     ///< the input plan's wall count
  std::size_t input_openings = 0;  ///< the input plan's opening count
};

/// @return the plan as built (slabs kept in order, their tops absolute).
/// @throws PreconditionError (not_buildable) naming the wall, as chord_polyline does for an
///         arc it cannot build. O(n + chords).
[[nodiscard]] BuildablePlan make_buildable(const Plan& plan);

/// Relabels faces built from `b.plan` (Model::objects indices of it: its walls, then its
/// openings, then its slabs) with the input plan's indices. O(faces).
void label_input_objects(const BuildablePlan& b, std::vector<FaceSoup>& soups);

}  // namespace roomcad::detail
