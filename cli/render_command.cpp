// roomcad render PLAN -o OUT.png: a picture of the plan's model from the CPU renderer.
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "io/id_image.h"
#include "io/image_io.h"
#include "modeling/build_model.h"
#include "modeling/value_text.h"
#include "render/renderer.h"

namespace roomcad::cli {
namespace {

/// The command line as given; turned into RenderOptions by make_options.
struct RenderArgs {
  std::string plan, output, depth, ids;
  int width = 1280, height = 720, shadow_res = 1024, ssaa = 1, threads = 0;
  std::string camera, eye, target, up = "0,0,1", projection = "perspective", view;
  double fov = 50.0, view_height = 10.0;
  std::string shading = "phong", shadows = "pcf", background = "#ffffff", grid = "on";
  std::string parts = "walls,floor,fixtures", cull = "back", frustum_cull = "on";
  std::string level;  ///< render only this level; empty: all
  bool stats = false, force = false;
};

/// @return the flag's value as x,y,z. @throws PreconditionError (usage_error) naming it.
Vec3 require_vec3(const std::string& flag, const std::string& text) {
  if (const std::optional<Vec3> v = parse_vec3(text)) return *v;
  throw_usage_error(fmt::format("{} '{}': expected three finite numbers x,y,z (metres)", flag, text));
}

/// The camera the flags ask for, or nullopt to frame the model from a preset.
std::optional<Camera> chosen_camera(const RenderArgs& a, const Plan& plan, Projection projection) {
  if (!a.camera.empty()) {
    for (const Camera& c : plan.cameras)
      if (c.id == a.camera) return c;
    std::string known;
    for (const Camera& c : plan.cameras) known += (known.empty() ? "" : ", ") + c.id;
    throw_usage_error(fmt::format("--camera '{}': the plan has no such camera (it has: {})", a.camera,
                              known.empty() ? "none" : known));
  }
  if (a.eye.empty() != a.target.empty()) {
    throw_usage_error("--eye and --target go together: give both or neither");
  }
  if (a.eye.empty()) return std::nullopt;
  Camera c;
  c.id = "flags";
  c.projection = projection;
  c.eye = require_vec3("--eye", a.eye);
  c.target = require_vec3("--target", a.target);
  c.up = require_vec3("--up", a.up);
  c.fov_deg = a.fov;
  c.view_height = a.view_height;
  if (c.eye == c.target) throw_usage_error(fmt::format("--eye and --target are both '{}'", a.eye));
  return c;
}

template <class T>
T parse_choice(const std::string& flag, const std::string& text, std::optional<T> parsed,
               const char* choices) {
  if (!parsed) throw_usage_error(fmt::format("{} '{}': expected one of {}", flag, text, choices));
  return *parsed;
}

/// The frame limits of render/renderer.h that no single flag's range can hold (each flag's own
/// range is checked as it is parsed), worded with the flags that set them.
/// @throws PreconditionError (usage_error) naming the flags, their values and the limit.
void check_frame_size(const RenderArgs& a) {
  const long long pixels = static_cast<long long>(a.width) * a.height;
  if (pixels > kMaxImagePixels) {
    throw_usage_error(fmt::format("--width {} x --height {} is {} pixels; at most {} are rendered",
                              a.width, a.height, pixels, kMaxImagePixels));
  }
  const long long samples = pixels * a.ssaa * a.ssaa;
  if (samples > kMaxImageSamples) {
    throw_usage_error(fmt::format("--width {} x --height {} at --ssaa {} is {} samples; at most {} are "
                              "rendered (lower --ssaa or the size)",
                              a.width, a.height, a.ssaa, samples, kMaxImageSamples));
  }
}

RenderOptions make_options(const RenderArgs& a, const Plan& plan) {
  check_frame_size(a);
  const Projection projection = parse_choice<Projection>(
      "--projection", a.projection,
      a.projection == "perspective"    ? std::optional(Projection::perspective)
      : a.projection == "orthographic" ? std::optional(Projection::orthographic)
                                       : std::nullopt,
      "perspective, orthographic");
  RenderOptions o{.width = a.width, .height = a.height};
  o.camera = chosen_camera(a, plan, projection);
  if (!a.view.empty()) {
    o.view = parse_choice("--view", a.view, parse_view_preset(a.view), "front, back, left, right, top, iso");
  }
  o.view_projection = projection;
  o.view_fov_deg = a.fov;
  o.shading = parse_choice("--shading", a.shading, parse_shading_mode(a.shading), "unlit, flat, gouraud, phong");
  o.shadows = parse_choice<ShadowFilter>(
      "--shadows", a.shadows,
      a.shadows == "off" ? std::optional(ShadowFilter::off)
      : a.shadows == "hard" ? std::optional(ShadowFilter::hard)
      : a.shadows == "pcf" ? std::optional(ShadowFilter::pcf) : std::nullopt,
      "off, hard, pcf");
  o.shadow_resolution = a.shadow_res;
  o.ssaa = a.ssaa;
  o.background = parse_choice("--background", a.background, parse_color(a.background), "#rrggbb");
  if (a.grid != "on" && a.grid != "off") throw_usage_error(fmt::format("--grid '{}': expected on or off", a.grid));
  o.grid = GridLines{.enabled = a.grid == "on", .origin = {plan.site.origin.x, plan.site.origin.y},
                     .cell_size = plan.site.cell_size, .cells = plan.site.cells};
  o.lights = plan.lights;
  const Result<Parts> parts = parse_parts(a.parts);
  if (!parts) throw PreconditionError(parts.error());
  o.parts = parts.value();
  o.threads = a.threads;
  o.outputs = FrameOutputs{.depth = !a.depth.empty(), .object_ids = !a.ids.empty()};
  o.cull = a.cull == "visibility" ? FaceCull::visibility
           : a.cull == "none"       ? FaceCull::none
                                    : FaceCull::back_faces;
  o.cull_frustum = a.frustum_cull == "on";
  throw_if_failed(check_render_options(o), "render");
  return o;
}

/// Writes the requested files. @return the first failure, if one could not be written.
Status write_outputs(const RenderArgs& a, const FrameBuffers& out, const Model& model) {
  if (Status s = write_png(out.color, a.output); !s) return s;
  if (!a.depth.empty())
    if (Status s = write_pfm(out.depth, a.depth); !s) return s;
  if (!a.ids.empty()) return write_object_ids(out.objects, model.objects, a.ids);
  return Status::success();
}

int run_render(const RenderArgs& a) {
  // The validation gate: errors stop the render unless --force.
  const LoadedPlan loaded = load_valid_plan("render", a.plan, a.force);
  if (!loaded.plan) return loaded.exit_status;
  const Result<Plan> level = select_level(*loaded.plan, a.level);
  if (!level) return report_failure("render", level.error());
  const Plan& plan = level.value();
  const RenderOptions options = make_options(a, plan);  // PreconditionError: main reports it
  if (plan.lights.size() > static_cast<std::size_t>(kMaxLights)) {
    std::fprintf(stderr, "roomcad render: warning: %s has %zu lights; the first %d are drawn\n",
                 a.plan.c_str(), plan.lights.size(), kMaxLights);
  }
  const Model model = build_model(plan, BuildOptions{.parts = options.parts, .threads = a.threads});
  FrameBuffers out;
  RenderStats stats;
  render_model(model, options, out, &stats);
  if (a.stats) {
    std::fprintf(stderr,
                 "{\"triangles\": %zu, \"screen_triangles\": %zu, \"shadow_ms\": %.3f, "
                 "\"raster_ms\": %.3f, \"frame_ms\": %.3f, \"width\": %d, \"height\": %d, "
                 "\"culled_triangles\": %zu, \"cull_ms\": %.3f}\n",
                 stats.triangles, stats.screen_triangles, stats.shadow_ms, stats.raster_ms,
                 stats.frame_ms, options.width, options.height, stats.culled_triangles,
                 stats.cull_ms);
  }
  if (const Status written = write_outputs(a, out, model); !written)
    return report_failure("render", written.error());
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* app = root.add_subcommand("render", "Render a picture of the plan's 3D model (PNG)");
  app->add_option("plan", args->plan, "The plan file (JSON)")->required();
  app->add_option("-o,--output", args->output, "The picture to write (PNG)")->required();
  const auto pixels = CLI::Range(1, kMaxImageSide);
  app->add_option("--width", args->width, "Picture width in pixels")->check(pixels)->capture_default_str();
  app->add_option("--height", args->height, "Picture height in pixels")->check(pixels)->capture_default_str();
  app->add_option("--camera", args->camera, "Use the plan's camera with this id");
  app->add_option("--eye", args->eye, "Camera position x,y,z (metres), with --target");
  app->add_option("--target", args->target, "Point looked at x,y,z (metres), with --eye");
  app->add_option("--up", args->up, "Camera up direction x,y,z")->capture_default_str();
  app->add_option("--fov", args->fov, "Vertical field of view, degrees (perspective)")
      ->check(CLI::Range(1e-3, 179.999))->capture_default_str();
  app->add_option("--projection", args->projection, "perspective or orthographic")->capture_default_str();
  app->add_option("--view-height", args->view_height, "Metres seen vertically (orthographic)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app->add_option("--level", args->level,
                  "Render only the level with this id (its walls, openings and slabs, at their "
                  "height)");
  app->add_option("--view", args->view, "Frame the model from front|back|left|right|top|iso (default iso)");
  app->add_option("--shading", args->shading, "unlit, flat, gouraud or phong")->capture_default_str();
  app->add_option("--shadows", args->shadows, "off, hard or pcf")->capture_default_str();
  app->add_option("--shadow-res", args->shadow_res, "Shadow-map texels per side")
      ->check(CLI::Range(1, kMaxShadowResolution))->capture_default_str();
  app->add_option("--ssaa", args->ssaa, "Supersampling per pixel side: 1, 2 or 4")
      ->check(CLI::IsMember({1, 2, 4}))->capture_default_str();
  app->add_option("--background", args->background, "Background colour #rrggbb")->capture_default_str();
  app->add_option("--grid", args->grid, "Draw the site's tiles on the floor: on or off")->capture_default_str();
  app->add_option("--parts", args->parts, "Parts to draw: walls,floor,fixtures")->capture_default_str();
  app->add_option("--cull", args->cull,
                  "none: draw every face; back: skip faces turned away; visibility: also faces "
                  "the seed-004 pre-pass finds hidden (same picture)")
      ->check(CLI::IsMember({"none", "back", "visibility"}))
      ->capture_default_str();
  app->add_option("--frustum-cull", args->frustum_cull,
                  "on: skip clusters outside the view; off: clip them all (same picture)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  app->add_option("--depth", args->depth, "Also write the depth (metres along the view) as PFM");
  app->add_option("--ids", args->ids, "Also write object ids as PNG, with a JSON legend beside it");
  app->add_option("--threads", args->threads, "Threads, 0 = all cores (same picture at any count)")
      ->check(CLI::Range(0, kMaxThreads));
  app->add_flag("--force", args->force, "Render even if the plan has validation errors");
  app->add_flag("--stats", args->stats, "Print triangles and timings as one JSON line on stderr");
  commands.push_back({app, [args] { return run_render(*args); }});
}

}  // namespace roomcad::cli
