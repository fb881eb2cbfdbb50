// SPDX-License-Identifier: GPL-3.0-or-later
// A picture asked for in words, as `roomcad render`'s flags and the Python module's
// Plan.render arguments give it, and the RenderOptions it means for a plan. Both front ends
// fill a RenderRequest, so their defaults and their checks are the same.
#pragma once

#include <optional>
#include <string>

#include "plan/plan.h"
#include "render/renderer.h"

namespace roomcad {

/// The defaults are the command's. Texts are as on the command line: points "x,y,z",
/// colours "#rrggbb", lists "walls,floor".
struct RenderRequest {
  int width = 1280, height = 720, shadow_res = 1024, ssaa = 1, threads = 0;
  std::string camera;       ///< a plan camera's id, or empty
  std::string eye, target;  ///< both or neither: a camera given by its points (metres)
  std::string up = "0,0,1", projection = "perspective";
  std::string view;  ///< front, back, left, right, top, iso; empty: iso
  double fov = 50.0, view_height = 10.0;
  std::string shading = "phong", shadows = "pcf", background = "#ffffff", grid = "on";
  std::string parts = kAllParts, cull = "back", frustum_cull = "on";
  /// The unit direction towards the sun in plan coordinates (daylight's sun_direction_in_plan),
  /// or nullopt: an outdoor picture lit by the sun and the sky in place of the plan's lights
  /// (sun_and_sky_light), with the plan's obstructions; z <= 0, the sky alone.
  std::optional<Vec3> sun;
};

/// @return the options that render `plan` as `request` asks (no depth or id image: set
///         `outputs` for those), checked by check_render_options; or a usage_error naming the
///         first flag that is wrong and its value: an unknown camera, a malformed point or
///         colour, an unknown choice, a frame too large.
[[nodiscard]] Result<RenderOptions> make_render_options(const RenderRequest& request,
                                                        const Plan& plan);

}  // namespace roomcad
