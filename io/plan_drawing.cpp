// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/plan_drawing.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <map>

#include <fmt/format.h>

#include "io/floor_plan_svg.h"
#include "plan/plan_chords.h"
#include "plan/plan_levels.h"
#include "render/floor_plan.h"
#include "render/line_drawing.h"
#include "solid/build_model.h"

namespace roomcad {
namespace {

/// A view: draws a validated plan with checked options (scale = the N of 1:N).
/// @return the document, or why this view cannot draw this plan.
using ViewDrawer = std::function<Result<SvgDocument>(const Plan&, const DrawRequest&, double)>;

/// The plan a floor plan (drawn from the plan, not the mesh) is drawn from: arcs as their
/// chords, heights as the cut sees them: on one level (`on_level`) measured from its floor,
/// so the cut is at the cut height above its elevation; else absolute.
Plan floor_plan_input(const Plan& plan, bool on_level) {
  Plan heights = plan;
  if (on_level) {
    for (Wall& w : heights.walls) w.level.clear();  // bases stay measured from its floor
    for (Slab& s : heights.slabs) s.level.clear();
  } else {
    heights = with_absolute_heights(std::move(heights));
  }
  return with_arcs_as_chords(heights).plan;
}

/// The floor plan of a plan already cut to request.level (select_level).
FloorPlanDrawing draw_floor_plan_of(const Plan& shown, const DrawRequest& o, double scale) {
  FloorPlanOptions options{.scale = scale, .cut_height = o.cut_height};
  options.marks = o.marks;
  return draw_floor_plan(floor_plan_input(shown, !o.level.empty()), options);
}

Result<SvgDocument> draw_plan_view(const Plan& plan, const DrawRequest& o, double scale) {
  const std::string title = o.level.empty()
                                ? fmt::format("{}: floor plan", o.title)
                                : fmt::format("{}: floor plan of level {}", o.title, o.level);
  return make_floor_plan_svg(draw_floor_plan_of(plan, o, scale), title);
}

/// Draws the model of `plan` as seen by `view` (hidden lines removed).
Result<SvgDocument> draw_model_view(const Plan& plan, const DrawRequest& o, double scale,
                                    const LineView& view) {
  LineDrawingOptions options{.scale = scale,
                             .hidden = o.hidden == "off" ? HiddenLines::off : HiddenLines::dashed};
  const Result<Parts> parts = parse_parts(o.parts);
  if (!parts) return parts.error();
  options.parts = parts.value();
  // A model that cannot be built throws PreconditionError (not_buildable): main reports it.
  const Model model = build_model(plan, BuildOptions{.parts = options.parts});
  const LineDrawing drawing = draw_line_view(model, view, options, o.title);
  return make_line_drawing_svg(drawing, fmt::format("{}: {}", o.title, view.name));
}

ViewDrawer preset_drawer(const std::string& name) {
  return [name](const Plan& plan, const DrawRequest& o, double scale) {
    return draw_model_view(plan, o, scale, *preset_line_view(name));
  };
}

const std::map<std::string, ViewDrawer>& views() {
  static const std::map<std::string, ViewDrawer> table{
      {"plan", draw_plan_view},          {"north", preset_drawer("north")},
      {"south", preset_drawer("south")}, {"east", preset_drawer("east")},
      {"west", preset_drawer("west")},   {"iso", preset_drawer("iso")}};
  return table;
}

/// The drawer of a view name: a table entry, or camera:ID of the plan's cameras.
Result<ViewDrawer> find_view(const std::string& name, const Plan& plan) {
  if (const auto it = views().find(name); it != views().end()) return it->second;
  if (!name.starts_with(kCameraViewPrefix) || name.size() == kCameraViewPrefix.size()) {
    std::string known;
    for (const auto& [view, drawer] : views()) known += view + ", ";
    return Result<ViewDrawer>::failure(
        Code::usage_error, fmt::format("--view \"{}\": expected {}or camera:ID", name, known));
  }
  const std::string id = name.substr(kCameraViewPrefix.size());
  std::string known;
  for (const Camera& c : plan.cameras) {
    if (c.id == id) {
      return ViewDrawer([c](const Plan& p, const DrawRequest& o, double scale) {
        return draw_model_view(p, o, scale, camera_line_view(c));
      });
    }
    known += (known.empty() ? "" : ", ") + c.id;
  }
  return Result<ViewDrawer>::failure(
      Code::usage_error, fmt::format("--view \"{}\": the plan has no camera \"{}\" (it has: {})",
                                     name, id, known.empty() ? "none" : known));
}

/// Parses "1:N" or "N" into N. @return NaN if the text is neither.
double parse_scale(const std::string& text) {
  const std::string number = text.rfind("1:", 0) == 0 ? text.substr(2) : text;
  double value = NAN;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
  return ec == std::errc{} && end == number.data() + number.size() ? value : NAN;
}

}  // namespace

std::vector<std::string> drawing_view_names() {
  std::vector<std::string> names;
  for (const auto& [name, drawer] : views()) names.push_back(name);
  return names;
}

Status check_draw_request(const DrawRequest& request) {
  const double scale = parse_scale(request.scale);
  if (std::isnan(scale))
    return Error{Code::usage_error,
                 fmt::format("--scale \"{}\": expected 1:N, e.g. 1:50", request.scale)};
  if (request.hidden != "dashed" && request.hidden != "off")
    return Error{Code::usage_error,
                 fmt::format("--hidden \"{}\": expected dashed or off", request.hidden)};
  return check_floor_plan_options({.scale = scale, .cut_height = request.cut_height});
}

Result<FloorPlanDrawing> draw_requested_floor_plan(const Plan& plan, const DrawRequest& request) {
  if (const Status checked = check_draw_request(request); !checked) return checked.error();
  const Result<Plan> shown = select_level(plan, request.level);
  if (!shown) return shown.error();
  return draw_floor_plan_of(shown.value(), request, parse_scale(request.scale));
}

Result<SvgDocument> draw_plan_svg(const Plan& plan, const DrawRequest& request) {
  if (const Status checked = check_draw_request(request); !checked) return checked.error();
  const Result<Plan> shown = select_level(plan, request.level);
  if (!shown) return shown.error();
  const Result<ViewDrawer> drawer = find_view(request.view, plan);
  if (!drawer) return drawer.error();
  return drawer.value()(shown.value(), request, parse_scale(request.scale));
}

}  // namespace roomcad
