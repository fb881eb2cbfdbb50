// `roomcad draw`: line drawings of a plan as SVG: the floor plan, elevations, isometric and
// camera views (render/line_drawing.h) with hidden lines removed. Views are looked up in one
// table; `camera:ID` names a plan camera.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "cli/rule_loading.h"
#include "io/floor_plan_svg.h"
#include "render/floor_plan.h"
#include "render/line_drawing.h"
#include "validation/validate.h"

namespace roomcad::cli {
namespace {

struct DrawOptions {
  std::filesystem::path plan_file;
  std::string view = "plan";
  std::string scale = "1:50";
  double cut_height = 1.0;
  std::string hidden = "dashed";
  std::string parts = "walls,floor,fixtures";
  std::filesystem::path output;
  bool force = false;
  bool findings = false;
  std::string rules = "all";
};

constexpr std::string_view kCameraPrefix = "camera:";

/// A view: draws a validated plan with checked options (scale = the N of 1:N).
/// @return the document, or why this view cannot draw this plan.
using ViewDrawer = std::function<Result<SvgDocument>(const Plan&, const DrawOptions&, double)>;

/// @return the places of what `validate --rules` finds (errors, warnings, rule findings),
///         each with its code; items without a place are left out.
Result<std::vector<PlanMark>> find_marks(const Plan& plan, const std::string& rules) {
  const Result<RuleSet> set = load_rule_set(rules);
  if (!set) return set.error();
  if (const Status rooms = check_accessible_rooms(plan, set.value()); !rooms) return rooms.error();
  ValidateOptions options;
  options.rules = set.value();
  std::vector<PlanMark> marks;
  for (const Diagnostic& d : validate(plan, options).items)
    if (d.where) marks.push_back({std::string(to_string(d.code)), d.where->min, d.where->max});
  return marks;
}

Result<SvgDocument> draw_plan_view(const Plan& plan, const DrawOptions& o, double scale) {
  FloorPlanOptions options;
  options.scale = scale;
  options.cut_height = o.cut_height;
  if (o.findings) {
    Result<std::vector<PlanMark>> marks = find_marks(plan, o.rules);
    if (!marks) return marks.error();
    options.marks = std::move(marks).value();
  }
  return make_floor_plan_svg(draw_floor_plan(plan, options),
                             fmt::format("{}: floor plan", o.plan_file.filename().string()));
}

/// Draws the model of `plan` as seen by `view` (hidden lines removed).
Result<SvgDocument> draw_model_view(const Plan& plan, const DrawOptions& o, double scale,
                                    const LineView& view) {
  LineDrawingOptions options{.scale = scale,
                             .hidden = o.hidden == "off" ? HiddenLines::off : HiddenLines::dashed};
  const Result<Parts> parts = parse_parts(o.parts);
  if (!parts) return parts.error();
  options.parts = parts.value();
  // A model that cannot be built throws PreconditionError (not_buildable): main reports it.
  const Model model = build_model(plan, BuildOptions{.parts = options.parts});
  const std::string title = o.plan_file.filename().string();
  const LineDrawing drawing = draw_line_view(model, view, options, title);
  return make_line_drawing_svg(drawing, fmt::format("{}: {}", title, view.name));
}

ViewDrawer preset_drawer(const std::string& name) {
  return [name](const Plan& plan, const DrawOptions& o, double scale) {
    return draw_model_view(plan, o, scale, *preset_line_view(name));
  };
}

const std::map<std::string, ViewDrawer>& views() {
  static const std::map<std::string, ViewDrawer> table{
      {"plan", draw_plan_view},         {"north", preset_drawer("north")},
      {"south", preset_drawer("south")}, {"east", preset_drawer("east")},
      {"west", preset_drawer("west")},   {"iso", preset_drawer("iso")}};
  return table;
}

/// The drawer of a view name: a table entry, or camera:ID of the plan's cameras.
Result<ViewDrawer> find_view(const std::string& name, const Plan& plan) {
  if (const auto it = views().find(name); it != views().end()) return it->second;
  const std::string id = name.substr(kCameraPrefix.size());
  std::string known;
  for (const Camera& c : plan.cameras) {
    if (c.id == id) {
      return ViewDrawer([c](const Plan& p, const DrawOptions& o, double scale) {
        return draw_model_view(p, o, scale, camera_line_view(c));
      });
    }
    known += (known.empty() ? "" : ", ") + c.id;
  }
  return Result<ViewDrawer>::failure(Code::usage_error,
      fmt::format("--view \"{}\": the plan has no camera \"{}\" (it has: {})", name, id,
                  known.empty() ? "none" : known));
}

/// Parses "1:N" or "N" into N. @return NaN if the text is neither.
double parse_scale(const std::string& text) {
  const std::string number = text.rfind("1:", 0) == 0 ? text.substr(2) : text;
  double value = NAN;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
  return ec == std::errc{} && end == number.data() + number.size() ? value : NAN;
}

int run_draw(const DrawOptions& o) {
  const double scale = parse_scale(o.scale);
  if (std::isnan(scale))
    return report_failure("draw", {Code::usage_error,
                                   fmt::format("--scale \"{}\": expected 1:N, e.g. 1:50", o.scale)});
  FloorPlanOptions plan_options;
  plan_options.scale = scale;
  plan_options.cut_height = o.cut_height;
  if (const Status options = check_floor_plan_options(plan_options); !options)
    return report_failure("draw", options.error());
  if (o.output.extension() != ".svg")
    return report_failure("draw", {Code::unsupported, fmt::format("-o \"{}\": drawings are "
                                                                  "written as .svg", o.output.string())});
  if (o.findings && o.view != "plan")
    return report_failure("draw", {Code::usage_error, fmt::format("--findings: only the plan view marks "
                                                                  "findings, not --view {}", o.view)});
  const LoadedPlan loaded = load_valid_plan("draw", o.plan_file, o.force);
  if (!loaded.plan) return loaded.exit_status;
  const Result<ViewDrawer> drawer = find_view(o.view, *loaded.plan);
  if (!drawer) return report_failure("draw", drawer.error());
  const Result<SvgDocument> document = drawer.value()(*loaded.plan, o, scale);
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
      "Draw a plan as an SVG line drawing on paper at a scale.\n"
      "  plan: the architectural floor plan, a horizontal section at --cut-height: cut walls\n"
      "        filled, windows as three lines, doors with leaf and swing, rooms with name and\n"
      "        area, per-wall and overall dimensions (metres), a scale bar.\n"
      "  north|south|east|west: orthographic elevations named after the face shown (north:\n"
      "        standing north, looking south); iso: isometric from the south-west;\n"
      "        camera:ID: the plan camera's view. Feature edges only; hidden lines removed\n"
      "        exactly, drawn dashed (--hidden dashed) or left out (--hidden off).\n"
      "Examples: roomcad draw house.json --view plan --scale 1:50 -o house-plan.svg\n"
      "          roomcad draw house.json --findings --rules accessibility -o findings.svg");
  app->add_option("PLAN", o->plan_file, "the plan file (JSON)")->required();
  std::vector<std::string> names;
  for (const auto& [name, drawer] : views()) names.push_back(name);
  const CLI::Validator known_view(
      [names](std::string& v) -> std::string {
        if (v.rfind(kCameraPrefix, 0) == 0 && v.size() > kCameraPrefix.size()) return {};
        if (std::find(names.begin(), names.end(), v) != names.end()) return {};
        return fmt::format("\"{}\" is not {} or camera:ID", v, fmt::join(names, ", "));
      },
      "VIEW");
  app->add_option("--view", o->view, "which drawing: plan, north, south, east, west, iso, camera:ID")
      ->check(known_view)
      ->capture_default_str();
  app->add_option("--hidden", o->hidden, "hidden edges of views: dashed or off")
      ->check(CLI::IsMember({"dashed", "off"}))
      ->capture_default_str();
  app->add_option("--parts", o->parts, "parts a view draws: walls,floor,fixtures (floor as outline)")
      ->capture_default_str();
  app->add_option("--scale", o->scale, "paper scale 1:N, between 1:1 and 1:10000")
      ->capture_default_str();
  app->add_option("--cut-height", o->cut_height, "height of the plan's section, metres")
      ->capture_default_str();
  app->add_option("-o,--output", o->output, "OUT.svg (written atomically)")->required();
  app->add_flag("--force", o->force, "Draw even if the plan has validation errors");
  app->add_flag("--findings", o->findings,
                "plan view: mark what validate --rules finds in red, with its code");
  app->add_option("--rules", o->rules, "the rule set of --findings: default, accessibility, all or a rules file")
      ->type_name("NAME|FILE")
      ->capture_default_str();
  commands.push_back({app, [o] { return run_draw(*o); }});
}

}  // namespace roomcad::cli
