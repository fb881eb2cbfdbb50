// SPDX-License-Identifier: GPL-3.0-or-later
// A line drawing of a plan asked for in words, as `roomcad draw`'s flags and the Python
// module's Plan.draw give it: the floor plan, elevations, isometric and camera views
// (render/line_drawing.h) as SVG. Views are looked up in one table; `camera:ID` names a camera.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "io/svg_writer.h"
#include "plan/plan.h"
#include "render/floor_plan.h"

namespace roomcad {

/// The prefix of a view that names a plan camera: "camera:ID".
inline constexpr std::string_view kCameraViewPrefix = "camera:";

/// The defaults are the command's.
struct DrawRequest {
  std::string view = "plan";      ///< plan, north, south, east, west, iso, or camera:ID
  std::string scale = "1:50";     ///< paper scale 1:N (or N)
  double cut_height = 1.0;        ///< metres, the floor plan's section
  std::string hidden = "dashed";  ///< hidden edges of views: dashed or off
  std::string parts = "walls,floor,fixtures";
  std::string title;  ///< the drawing's title starts with it (the plan file's name)
  std::string level;  ///< draw only this level (plan format version 2); empty: every level
  std::vector<PlanMark> marks{};  ///< findings the plan view marks in red (draw --findings)
};

/// @return the names of the views the table holds (camera:ID aside), sorted.
[[nodiscard]] std::vector<std::string> drawing_view_names();

/// Checks what needs no plan: the scale, the cut height, `hidden`.
/// @return success, or a usage_error naming the option and its value.
[[nodiscard]] Status check_draw_request(const DrawRequest& request);

/// The floor plan `request` asks for (level, scale, cut height, marks), for the SVG plan view
/// and the DXF: arcs drawn as their chords; with a level, its walls cut at the cut height above
/// its floor, else every wall at its absolute height.
/// @return the drawing, or a usage_error (bad options, unknown level). O(plan + drawing).
[[nodiscard]] Result<FloorPlanDrawing> draw_requested_floor_plan(const Plan& plan,
                                                                 const DrawRequest& request);

/// Draws `plan` (validated: errors are drawn as they are) as `request` asks.
/// @return the document, or a usage_error (unknown view or camera, bad options or parts).
/// @throws PreconditionError (not_buildable) for a view of a model that cannot be built.
[[nodiscard]] Result<SvgDocument> draw_plan_svg(const Plan& plan, const DrawRequest& request);

}  // namespace roomcad
