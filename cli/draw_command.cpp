// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad draw`: line drawings of a plan as SVG: the floor plan, elevations, isometric and
// camera views (render/line_drawing.h) with hidden lines removed. Views are looked up in one
// table; `camera:ID` names a plan camera.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "io/floor_plan_dxf.h"
#include "io/plan_drawing.h"
#include "io/rule_set_file.h"
#include "io/svg_writer.h"
#include "render/floor_plan.h"
#include "validation/validate.h"

namespace roomcad::cli {
namespace {

struct DrawOptions {
  std::filesystem::path plan_file;
  DrawRequest request;
  std::filesystem::path output;
  bool force = false;
  bool verbose = false;  ///< list the plan's findings (else one line counts them)
  bool findings = false;
  std::string rules = "all";
};

/// @return the places of what `validate --rules` finds (errors, warnings, rule findings),
///         each with its code; items without a place are left out.
Result<std::vector<PlanMark>> find_marks(const Plan& plan, const std::string& rules) {
  const Result<RuleSet> set = load_rule_set(rules, "--rules");
  if (!set) return set.error();
  if (const Status rooms = check_accessible_rooms(plan, set.value()); !rooms) return rooms.error();
  ValidateOptions options;
  options.rules = set.value();
  std::vector<PlanMark> marks;
  for (const Diagnostic& d : validate(plan, options).items)
    if (d.where) marks.push_back({std::string(to_string(d.code)), d.where->min, d.where->max});
  return marks;
}

int run_draw(const DrawOptions& o) {
  DrawRequest request = o.request;
  request.title = o.plan_file.filename().string();
  if (const Status checked = check_draw_request(request); !checked)
    return report_failure("draw", checked.error());
  const bool dxf = o.output.extension() == ".dxf";
  if (o.output.extension() != ".svg" && !(dxf && request.view == "plan"))
    return report_failure("draw",
                          {Code::unsupported, fmt::format("-o \"{}\": drawings are written "
                                                          "as .svg (and the plan view as .dxf too)",
                                                          o.output.string())});
  if (o.findings && request.view != "plan")
    return report_failure("draw", {Code::usage_error, fmt::format("--findings: only the plan view "
                                                                  "marks findings, not --view {}",
                                                                  request.view)});
  const Result<LoadedPlan> loaded =
      load_valid_plan("draw", o.plan_file, o.force, findings_for(o.verbose));
  if (!loaded) return exit_status_of(loaded.code());
  if (o.findings) {
    Result<std::vector<PlanMark>> marks = find_marks(loaded->plan, o.rules);
    if (!marks) return report_failure("draw", marks.error());
    request.marks = std::move(marks).value();
  }
  if (dxf) {
    const Result<FloorPlanDrawing> drawing = draw_requested_floor_plan(loaded->plan, request);
    if (!drawing) return report_failure("draw", drawing.error());
    if (const Status written = write_floor_plan_dxf(drawing.value(), o.output); !written)
      return report_failure("draw", written.error());
    std::printf("wrote %s\n", o.output.string().c_str());
    return kExitOk;
  }
  // A model that cannot be built throws PreconditionError (not_buildable): main reports it.
  const Result<SvgDocument> document = draw_plan_svg(loaded->plan, request);
  if (!document) return report_failure("draw", document.error());
  if (const Status written = write_svg(document.value(), o.output); !written)
    return report_failure("draw", written.error());
  std::printf("wrote %s\n", o.output.string().c_str());
  return kExitOk;
}

}  // namespace

void add_draw_command(CLI::App& root, Commands& commands) {
  auto o = std::make_shared<DrawOptions>();
  CLI::App* app = root.add_subcommand(
      "draw",
      "Draw a plan as an SVG line drawing on paper at a scale (the plan view also as DXF).\n"
      "  plan: the architectural floor plan, a horizontal section at --cut-height: cut walls\n"
      "        filled, windows as three lines, doors with leaf and swing, rooms with name and\n"
      "        area, per-wall and overall dimensions (metres), a scale bar.\n"
      "  north|south|east|west: orthographic elevations named after the face shown (north:\n"
      "        standing north, looking south); iso: isometric from the south-west;\n"
      "        camera:ID: the plan camera's view. Feature edges only; hidden lines removed\n"
      "        exactly, drawn dashed (--hidden dashed) or left out (--hidden off).\n"
      "  -o OUT.dxf (plan view): the same drawing for CAD programs (AutoCAD 2000 DXF), in model\n"
      "        space at true size in metres, on layers WALLS_CUT (with solid hatches),\n"
      "        WALLS_BELOW, WALLS_ABOVE, WINDOWS, DOORS, DIMENSIONS and ROOMS.\n"
      "--level ID draws one level of a plan with levels: its floor plan is cut at --cut-height\n"
      "above the level's elevation; its views show its walls and slabs alone.\n"
      "Example: roomcad draw house.json --view plan --scale 1:50 -o house-plan.svg");
  app->add_option("PLAN", o->plan_file, "the plan file (JSON)")->required();
  std::vector<std::string> names;
  for (const std::string& name : drawing_view_names()) names.push_back(name);
  const CLI::Validator known_view(
      [names](std::string& v) -> std::string {
        if (v.rfind(kCameraViewPrefix, 0) == 0 && v.size() > kCameraViewPrefix.size()) return {};
        if (std::find(names.begin(), names.end(), v) != names.end()) return {};
        return fmt::format("\"{}\" is not {} or camera:ID", v, fmt::join(names, ", "));
      },
      "VIEW");
  app->add_option("--view", o->request.view,
                  "which drawing: plan, north, south, east, west, iso, camera:ID")
      ->check(known_view)
      ->capture_default_str();
  app->add_option("--hidden", o->request.hidden, "hidden edges of views: dashed or off")
      ->check(CLI::IsMember({"dashed", "off"}))
      ->capture_default_str();
  app->add_option("--parts", o->request.parts,
                  "parts a view draws: walls,slabs,floor,fixtures (floor as outline)")
      ->capture_default_str();
  app->add_option("--scale", o->request.scale, "paper scale 1:N, between 1:1 and 1:10000")
      ->capture_default_str();
  app->add_option("--cut-height", o->request.cut_height,
                  "height of the plan's section, metres (above the level's floor with --level)")
      ->capture_default_str();
  app->add_option("--level", o->request.level,
                  "draw only the level with this id (plan format version 2)");
  app->add_option("-o,--output", o->output,
                  "OUT.svg, or OUT.dxf for the plan view (written atomically)")
      ->required();
  app->add_flag("--force", o->force, "Draw even if the plan has validation errors");
  add_verbose_flag(*app, o->verbose);
  app->add_flag("--findings", o->findings,
                "plan view: mark what validate --rules finds in red, with its code");
  app->add_option(
      "--rules", o->rules,
      "the rule set of --findings: default, accessibility, insolation, all or a rules file");
  commands.push_back({app, [o] { return run_draw(*o); }});
}

}  // namespace roomcad::cli
