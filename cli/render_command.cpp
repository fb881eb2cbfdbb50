// SPDX-License-Identifier: GPL-3.0-or-later
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
#include "cli/site_place.h"
#include "daylight/sun_at.h"
#include "io/id_image.h"
#include "io/image_io.h"
#include "plan/plan_levels.h"
#include "render/render_request.h"
#include "render/renderer.h"
#include "solid/build_model.h"

namespace roomcad::cli {
namespace {

/// The command line as given: the picture's request (render/render_request.h) and the files.
struct RenderArgs {
  RenderRequest request;
  std::string plan, output, depth, ids;
  std::string level;  ///< render only this level; empty: all
  std::string sun;    ///< --sun TIME; empty: the plan's lights
  PlaceOptions place;
  bool stats = false, force = false;
  bool verbose = false;  ///< list the plan's findings (else one line counts them)
};

/// Writes the requested files. @return the first failure, if one could not be written.
Status write_outputs(const RenderArgs& a, const FrameBuffers& out, const Model& model) {
  if (Status s = write_png(out.color, a.output); !s) return s;
  if (!a.depth.empty())
    if (Status s = write_pfm(out.depth, a.depth); !s) return s;
  if (!a.ids.empty()) return write_object_ids(out.objects, model.objects, a.ids);
  return Status::success();
}

/// With --sun, points `request` at the sun (from the site's place at that time) and says on
/// stderr when it is down. @return a usage_error naming the option that is wrong.
Status light_by_sun(const RenderArgs& a, const Plan& plan, RenderRequest& request) {
  const bool placed = a.place.latitude || a.place.longitude || a.place.utc_offset;
  if (a.sun.empty()) {
    if (placed)
      return Status::failure(Code::usage_error,
                             "--latitude, --longitude and --utc-offset place the sun of --sun; "
                             "give --sun TIME with them");
    return Status::success();
  }
  const Result<GeoLocation> place = site_place(&plan, a.plan, a.place);
  if (!place) return place.status();
  const Result<SunAt> sun = sun_at(place.value(), plan.site.north.value_or(0.0), a.sun, "--sun");
  if (!sun) return sun.status();
  request.sun = sun->direction;
  if (sun->position.elevation <= 0) {
    std::fprintf(stderr,
                 "roomcad render: the sun is below the horizon at %s (elevation %.2f°): lit by "
                 "the sky alone\n",
                 site_clock_text(place.value(), sun->time).c_str(), sun->position.elevation);
  }
  return Status::success();
}

int run_render(const RenderArgs& a) {
  // The validation gate: errors stop the render unless --force.
  const Result<LoadedPlan> loaded =
      load_valid_plan("render", a.plan, a.force, findings_for(a.verbose));
  if (!loaded) return exit_status_of(loaded.code());
  const Result<Plan> level = select_level(loaded->plan, a.level);
  if (!level) return report_failure("render", level.error());
  const Plan& plan = level.value();
  RenderRequest request = a.request;
  if (const Status lit = light_by_sun(a, plan, request); !lit)
    return report_failure("render", lit.error());
  Result<RenderOptions> asked = make_render_options(request, plan);
  if (!asked) return report_failure("render", asked.error());
  RenderOptions options = std::move(asked).value();
  options.outputs = FrameOutputs{.depth = !a.depth.empty(), .object_ids = !a.ids.empty()};
  if (!request.sun && plan.lights.size() > static_cast<std::size_t>(kMaxLights)) {
    std::fprintf(stderr, "roomcad render: warning: %s has %zu lights; the first %d are drawn\n",
                 a.plan.c_str(), plan.lights.size(), kMaxLights);
  }
  const bool walk = options.cull == FaceCull::portals || options.cull == FaceCull::visibility;
  const Model model = build_model(
      plan, BuildOptions{.parts = options.parts, .threads = a.request.threads, .cells = walk});
  FrameBuffers out;
  RenderStats stats;
  render_model(model, options, out, &stats);
  if (a.stats) {
    std::fprintf(stderr,
                 "{\"triangles\": %zu, \"screen_triangles\": %zu, \"shadow_ms\": %.3f, "
                 "\"raster_ms\": %.3f, \"frame_ms\": %.3f, \"width\": %d, \"height\": %d, "
                 "\"culled_triangles\": %zu, \"cull_ms\": %.3f, \"cells_visited\": %zu, "
                 "\"drawn_triangles\": %zu}\n",
                 stats.triangles, stats.screen_triangles, stats.shadow_ms, stats.raster_ms,
                 stats.frame_ms, options.width, options.height, stats.culled_triangles,
                 stats.cull_ms, stats.cells_visited, stats.drawn_triangles);
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
  app->add_option("--width", args->request.width, "Picture width in pixels")
      ->check(pixels)
      ->capture_default_str();
  app->add_option("--height", args->request.height, "Picture height in pixels")
      ->check(pixels)
      ->capture_default_str();
  app->add_option("--camera", args->request.camera, "Use the plan's camera with this id");
  app->add_option("--eye", args->request.eye, "Camera position x,y,z (metres), with --target");
  app->add_option("--target", args->request.target, "Point looked at x,y,z (metres), with --eye");
  app->add_option("--up", args->request.up, "Camera up direction x,y,z")->capture_default_str();
  app->add_option("--fov", args->request.fov, "Vertical field of view, degrees (perspective)")
      ->check(CLI::Range(1e-3, 179.999))
      ->capture_default_str();
  app->add_option("--projection", args->request.projection, "perspective or orthographic")
      ->capture_default_str();
  app->add_option("--view-height", args->request.view_height,
                  "Metres seen vertically (orthographic)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app->add_option("--level", args->level,
                  "Render only the level with this id (its walls, openings and slabs, at their "
                  "height)");
  app->add_option("--view", args->request.view,
                  "Frame the model from front|back|left|right|top|iso (default iso)");
  app->add_option("--sun", args->sun,
                  "Light the model by the sun at this local time at the site, YYYY-MM-DDTHH:MM, "
                  "or with its own offset (Z, +03:00), and the sky: the plan's lights are not "
                  "used; the ground, the sky and the plan's obstructions (in outline) are drawn")
      ->type_name("TIME");
  add_place_options(*app, args->place);
  app->add_option("--shading", args->request.shading, "unlit, flat, gouraud or phong")
      ->capture_default_str();
  app->add_option("--shadows", args->request.shadows, "off, hard or pcf")->capture_default_str();
  app->add_option("--shadow-res", args->request.shadow_res, "Shadow-map texels per side")
      ->check(CLI::Range(1, kMaxShadowResolution))
      ->capture_default_str();
  app->add_option("--ssaa", args->request.ssaa, "Supersampling per pixel side: 1, 2 or 4")
      ->check(CLI::IsMember({1, 2, 4}))
      ->capture_default_str();
  app->add_option("--background", args->request.background, "Background colour #rrggbb")
      ->capture_default_str();
  app->add_option("--grid", args->request.grid, "Draw the site's tiles on the floor: on or off")
      ->capture_default_str();
  app->add_option("--parts", args->request.parts, "Parts to draw: walls,floor,fixtures")
      ->capture_default_str();
  app->add_option("--cull", args->request.cull,
                  "none: draw every face; back: skip faces turned away; portals: also the rooms "
                  "the camera's room does not see through its doors and windows; visibility: "
                  "also faces Makarov & Safin's visible-surface pre-pass finds hidden among those "
                  "(the same picture whichever)")
      ->check(CLI::IsMember({"none", "back", "portals", "visibility"}))
      ->capture_default_str();
  app->add_option("--frustum-cull", args->request.frustum_cull,
                  "on: skip clusters outside the view; off: clip them all (same picture)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  app->add_option("--depth", args->depth, "Also write the depth (metres along the view) as PFM");
  app->add_option("--ids", args->ids, "Also write object ids as PNG, with a JSON legend beside it");
  app->add_option("--threads", args->request.threads,
                  "Threads, 0 = all cores (same picture at any count)")
      ->check(CLI::Range(0, kMaxThreads));
  app->add_flag("--force", args->force, "Render even if the plan has validation errors");
  add_verbose_flag(*app, args->verbose);
  app->add_flag("--stats", args->stats, "Print triangles and timings as one JSON line on stderr");
  commands.push_back({app, [args] { return run_render(*args); }});
}

}  // namespace roomcad::cli
