// `roomcad draw`: line drawings of a plan as SVG. Views are looked up in one table, so the
// elevations and camera views can be added beside `plan` without touching the rest.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "io/floor_plan_svg.h"
#include "render/floor_plan.h"

namespace roomcad::cli {
namespace {

struct DrawOptions {
  std::filesystem::path plan_file;
  std::string view = "plan";
  std::string scale = "1:50";
  double cut_height = 1.0;
  std::filesystem::path output;
};

/// A view: draws a validated plan with checked options (scale = the N of 1:N).
/// @return the document, or why this view cannot draw this plan.
using ViewDrawer = std::function<Result<SvgDocument>(const Plan&, const DrawOptions&, double)>;

Result<SvgDocument> draw_plan_view(const Plan& plan, const DrawOptions& o, double scale) {
  const FloorPlanOptions options{.scale = scale, .cut_height = o.cut_height};
  return make_floor_plan_svg(draw_floor_plan(plan, options),
                             fmt::format("{}: floor plan", o.plan_file.filename().string()));
}

const std::map<std::string, ViewDrawer>& views() {
  static const std::map<std::string, ViewDrawer> table{{"plan", draw_plan_view}};
  return table;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "roomcad draw: error: %s\n", message.c_str());
  return kCannotRun;
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
  if (std::isnan(scale)) {
    return fail(fmt::format("--scale \"{}\": expected 1:N, e.g. 1:50", o.scale));
  }
  if (std::string problem = check_floor_plan_options({.scale = scale, .cut_height = o.cut_height});
      !problem.empty()) {
    return fail(problem);
  }
  if (o.output.extension() != ".svg") {
    return fail(fmt::format("-o \"{}\": drawings are written as .svg", o.output.string()));
  }
  const LoadedPlan loaded = load_valid_plan("draw", o.plan_file, /*force=*/false);
  if (!loaded.plan) return loaded.exit_status;
  Result<SvgDocument> document = views().at(o.view)(*loaded.plan, o, scale);
  if (!document.ok()) return fail(document.error());
  if (const Status written = write_svg(document.value(), o.output); !written.ok()) {
    return fail(written.error);
  }
  std::printf("wrote %s\n", o.output.string().c_str());
  return kOk;
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
      "Example: roomcad draw house.json --view plan --scale 1:50 -o house-plan.svg");
  app->add_option("PLAN", o->plan_file, "the plan file (JSON)")->required();
  std::vector<std::string> names;
  for (const auto& [name, drawer] : views()) names.push_back(name);
  app->add_option("--view", o->view, "which drawing")
      ->check(CLI::IsMember(names))
      ->capture_default_str();
  app->add_option("--scale", o->scale, "paper scale 1:N, between 1:1 and 1:10000")
      ->capture_default_str();
  app->add_option("--cut-height", o->cut_height, "height of the plan's section, metres")
      ->capture_default_str();
  app->add_option("-o,--output", o->output, "OUT.svg (written atomically)")->required();
  commands.push_back({app, [o] { return run_draw(*o); }});
}

}  // namespace roomcad::cli
