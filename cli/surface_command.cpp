// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad surface`: the floating-horizon drawing of y = f(x, z) as SVG or PNG.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "cli/command.h"
#include "io/image_io.h"
#include "io/surface_svg.h"
#include "render/floating_horizon.h"
#include "render/line_raster.h"
#include "render/surface_expression.h"

namespace roomcad::cli {
namespace {

constexpr double kMmPerPixel = 0.25;  // SVG paper size: 800 x 600 px -> 200 x 150 mm
constexpr double kMarginPixels = 10.0;

struct SurfaceOptions {
  std::string expression;
  std::string x_range;
  std::string z_range;
  std::optional<double> dx;
  std::optional<double> dz;
  double rotate_x = 30.0;
  double rotate_y = 20.0;
  bool keep_aspect = false;
  int width = 800;
  int height = 600;
  std::filesystem::path output;
};

Error usage_error(std::string message) { return {Code::usage_error, std::move(message), {}}; }

/// Evaluates a constant expression ("2", "-2*pi").
/// @return the value, or why it is not a finite constant (no x or z).
Result<double> evaluate_constant(const std::string& text) {
  const Result<SurfaceExpression> parsed = parse_surface_expression(text);
  if (!parsed) return parsed.error();
  const auto& ops = parsed.value().program();
  if (std::find_if(ops.begin(), ops.end(), [](ExprOp op) {
        return op == ExprOp::var_x || op == ExprOp::var_z;
      }) != ops.end())
    return usage_error("a bound must not use x or z");
  const double value = parsed.value().evaluate(0.0, 0.0);
  if (std::isnan(value)) return usage_error("the bound is not a finite number");
  return value;
}

/// Parses "A:B" into its bounds. @return the bounds, or a usage_error naming the option and text.
Result<std::pair<double, double>> parse_range(const std::string& option, const std::string& text) {
  const std::size_t colon = text.find(':');
  std::string why = "expected A:B, e.g. -2:2 or -2*pi:2*pi";
  if (colon != std::string::npos) {
    const Result<double> a = evaluate_constant(text.substr(0, colon));
    const Result<double> b = a ? evaluate_constant(text.substr(colon + 1)) : a;
    if (a && b) return std::pair(a.value(), b.value());
    why = a ? b.message() : a.message();
  }
  return usage_error(fmt::format("{} \"{}\": {}", option, text, why));
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

int run_surface(const SurfaceOptions& o) {
  Result<SurfaceExpression> parsed = parse_surface_expression(o.expression);
  if (!parsed)
    return report_failure(
        "surface", usage_error(fmt::format("EXPR \"{}\": {}", o.expression, parsed.message())));
  const SurfaceExpression expression = std::move(parsed).value();
  SurfaceView view{.rotate_x_deg = o.rotate_x, .rotate_y_deg = o.rotate_y};
  const Result<std::pair<double, double>> x = parse_range("--x", o.x_range);
  if (!x) return report_failure("surface", x.error());
  const Result<std::pair<double, double>> z = parse_range("--z", o.z_range);
  if (!z) return report_failure("surface", z.error());
  std::tie(view.x_min, view.x_max) = x.value();
  std::tie(view.z_min, view.z_max) = z.value();
  // Defaults: 100 steps along each section, 40 sections.
  view.dx = o.dx.value_or((view.x_max - view.x_min) / 100.0);
  view.dz = o.dz.value_or(view.z_max > view.z_min ? (view.z_max - view.z_min) / 40.0 : 1.0);
  const std::string ext = lower_extension(o.output);
  if (ext != ".svg" && ext != ".png")
    return report_failure("surface", {Code::unsupported, fmt::format("-o \"{}\": the output must "
                                                                     "end in .svg or .png",
                                                                     o.output.string())});
  const double unit = ext == ".svg" ? kMmPerPixel : 1.0;
  const SurfaceScreen screen{.width = o.width * unit,
                             .height = o.height * unit,
                             .margin = kMarginPixels * unit,
                             .columns = o.width,
                             .keep_aspect = o.keep_aspect};
  if (const Status request = check_surface_request(view, screen); !request)
    return report_failure("surface", request.error());
  const SurfaceDrawing drawing = draw_floating_horizon(
      [&expression](double x, double z) { return expression.evaluate(x, z); }, view, screen);
  const Status written = ext == ".svg"
                             ? write_svg(make_surface_svg(drawing, "y = " + o.expression), o.output)
                             : write_png(rasterise_surface(drawing), o.output);
  if (!written) return report_failure("surface", written.error());
  if (drawing.polylines.empty()) {
    std::fprintf(stderr,
                 "roomcad surface: warning: \"%s\" has no finite value on the range; "
                 "the picture is empty\n",
                 o.expression.c_str());
  }
  std::printf("wrote %s: %zu visible polylines\n", o.output.string().c_str(),
              drawing.polylines.size());
  return kExitOk;
}

}  // namespace

void add_surface_command(CLI::App& root, Commands& commands) {
  auto o = std::make_shared<SurfaceOptions>();
  CLI::App* app = root.add_subcommand(
      "surface",
      "Draw the surface y = f(x, z) by the floating-horizon method (hidden lines removed).\n"
      "EXPR uses x, z, numbers, + - * / ^ (right-associative), parentheses, pi, e and\n"
      "abs sqrt exp ln sin cos. Where f is undefined (sqrt(-1), ln(0), 1/0) the surface has a\n"
      "gap. An EXPR starting with '-' goes last, after --. Example:\n"
      "  roomcad surface 'x*x - z*z' --x -2:2 --z -2:2 -o saddle.svg");
  app->add_option("EXPR", o->expression, "the height y as an expression of x and z")->required();
  app->add_option("--x", o->x_range, "x range A:B; bounds may be constant expressions (-2*pi)")
      ->required();
  app->add_option("--z", o->z_range, "z range C:D (the sections z = const, front to back)")
      ->required();
  app->add_option("--dx", o->dx, "step along each section (default: range / 100)");
  app->add_option("--dz", o->dz, "step between sections (default: range / 40)");
  app->add_option("--rotate-x", o->rotate_x, "degrees about x, in (-90, 90); > 0 looks down")
      ->capture_default_str();
  app->add_option("--rotate-y", o->rotate_y, "degrees about y (applied first), in (-90, 90)")
      ->capture_default_str();
  app->add_flag("--keep-aspect", o->keep_aspect,
                "one scale for x and y (terrain); by default each axis fills the picture");
  app->add_option("--width", o->width, "picture width in pixels (SVG: 0.25 mm each)")
      ->check(CLI::Range(16, 4096))
      ->capture_default_str();
  app->add_option("--height", o->height, "picture height in pixels")
      ->check(CLI::Range(16, 4096))
      ->capture_default_str();
  app->add_option("-o,--output", o->output, "OUT.svg or OUT.png (written atomically)")->required();
  commands.push_back({app, [o] { return run_surface(*o); }});
}

}  // namespace roomcad::cli
