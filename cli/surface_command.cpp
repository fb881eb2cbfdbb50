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
#include <variant>

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

int fail(const std::string& message) {
  std::fprintf(stderr, "roomcad surface: error: %s\n", message.c_str());
  return kCannotRun;
}

/// Evaluates a constant expression ("2", "-2*pi"). @return the value, or nullopt with `error`.
std::optional<double> evaluate_constant(const std::string& text, std::string& error) {
  auto parsed = parse_surface_expression(text);
  if (const auto* e = std::get_if<ExpressionError>(&parsed)) {
    error = e->message;
    return std::nullopt;
  }
  const SurfaceExpression& expression = std::get<SurfaceExpression>(parsed);
  const auto& ops = expression.program();
  if (std::find_if(ops.begin(), ops.end(), [](ExprOp op) {
        return op == ExprOp::var_x || op == ExprOp::var_z;
      }) != ops.end()) {
    error = "a bound must not use x or z";
    return std::nullopt;
  }
  const double value = expression.evaluate(0.0, 0.0);
  if (std::isnan(value)) error = "the bound is not a finite number";
  return std::isnan(value) ? std::nullopt : std::optional<double>(value);
}

/// Parses "A:B" into its bounds. @return false with `error` naming the option and the value.
bool parse_range(const std::string& option, const std::string& text, double& lo, double& hi,
                 std::string& error) {
  const std::size_t colon = text.find(':');
  std::string why = "expected A:B, e.g. -2:2 or -2*pi:2*pi";
  if (colon != std::string::npos) {
    const auto a = evaluate_constant(text.substr(0, colon), why);
    const auto b = a ? evaluate_constant(text.substr(colon + 1), why) : std::nullopt;
    if (a && b) {
      lo = *a;
      hi = *b;
      return true;
    }
  }
  error = fmt::format("{} \"{}\": {}", option, text, why);
  return false;
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

int run_surface(const SurfaceOptions& o) {
  auto parsed = parse_surface_expression(o.expression);
  if (const auto* e = std::get_if<ExpressionError>(&parsed)) {
    return fail(fmt::format("EXPR \"{}\": {}", o.expression, e->message));
  }
  const auto expression = std::get<SurfaceExpression>(std::move(parsed));
  SurfaceView view{.rotate_x_deg = o.rotate_x, .rotate_y_deg = o.rotate_y};
  std::string error;
  if (!parse_range("--x", o.x_range, view.x_min, view.x_max, error) ||
      !parse_range("--z", o.z_range, view.z_min, view.z_max, error)) {
    return fail(error);
  }
  // Defaults: 100 steps along each section, 40 sections.
  view.dx = o.dx.value_or((view.x_max - view.x_min) / 100.0);
  view.dz = o.dz.value_or(view.z_max > view.z_min ? (view.z_max - view.z_min) / 40.0 : 1.0);
  const std::string ext = lower_extension(o.output);
  if (ext != ".svg" && ext != ".png") {
    return fail(fmt::format("-o \"{}\": the output must end in .svg or .png", o.output.string()));
  }
  const double unit = ext == ".svg" ? kMmPerPixel : 1.0;
  const SurfaceScreen screen{.width = o.width * unit,
                             .height = o.height * unit,
                             .margin = kMarginPixels * unit,
                             .columns = o.width,
                             .keep_aspect = o.keep_aspect};
  if (std::string problem = check_surface_request(view, screen); !problem.empty()) {
    return fail(problem);
  }
  const SurfaceDrawing drawing = draw_floating_horizon(
      [&expression](double x, double z) { return expression.evaluate(x, z); }, view, screen);
  const Status written = ext == ".svg"
                             ? write_svg(make_surface_svg(drawing, "y = " + o.expression), o.output)
                             : write_png(rasterise_surface(drawing), o.output);
  if (!written.ok()) return fail(written.error);
  if (drawing.polylines.empty()) {
    std::fprintf(stderr,
                 "roomcad surface: warning: \"%s\" has no finite value on the range; "
                 "the picture is empty\n",
                 o.expression.c_str());
  }
  std::printf("wrote %s: %zu visible polylines\n", o.output.string().c_str(),
              drawing.polylines.size());
  return kOk;
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
