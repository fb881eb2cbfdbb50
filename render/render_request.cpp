// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/render_request.h"

#include <optional>
#include <string>

#include <fmt/format.h>

#include "mesh/parts.h"
#include "mesh/solid_mesh.h"
#include "plan/value_text.h"

namespace roomcad {
namespace {

/// The first bad flag found, as the usage_error the request fails with.
class FirstProblem {
 public:
  /// Keeps `message` unless a problem was found already.
  void add(std::string message) {
    if (!message_) message_ = std::move(message);
  }
  [[nodiscard]] bool found() const { return message_.has_value(); }
  [[nodiscard]] Error error() const { return Error{Code::usage_error, *message_}; }

 private:
  std::optional<std::string> message_;
};

/// @return the flag's value as x,y,z, or a zero vector after noting the problem.
Vec3 require_vec3(const std::string& flag, const std::string& text, FirstProblem& problem) {
  if (const std::optional<Vec3> v = parse_vec3(text)) return *v;
  problem.add(fmt::format("{} '{}': expected three finite numbers x,y,z (metres)", flag, text));
  return {};
}

/// The camera the flags ask for, or nullopt to frame the model from a preset.
std::optional<Camera> chosen_camera(const RenderRequest& a, const Plan& plan, Projection projection,
                                    FirstProblem& problem) {
  if (!a.camera.empty()) {
    for (const Camera& c : plan.cameras)
      if (c.id == a.camera) return c;
    std::string known;
    for (const Camera& c : plan.cameras) known += (known.empty() ? "" : ", ") + c.id;
    problem.add(fmt::format("--camera '{}': the plan has no such camera (it has: {})", a.camera,
                            known.empty() ? "none" : known));
    return std::nullopt;
  }
  if (a.eye.empty() != a.target.empty()) {
    problem.add("--eye and --target go together: give both or neither");
    return std::nullopt;
  }
  if (a.eye.empty()) return std::nullopt;
  Camera c;
  c.id = "flags";
  c.projection = projection;
  c.eye = require_vec3("--eye", a.eye, problem);
  c.target = require_vec3("--target", a.target, problem);
  c.up = require_vec3("--up", a.up, problem);
  c.fov_deg = a.fov;
  c.view_height = a.view_height;
  if (!problem.found() && c.eye == c.target)
    problem.add(fmt::format("--eye and --target are both '{}'", a.eye));
  return c;
}

/// @return the parsed choice, or `T{}` after noting the flag, its text and the choices.
template <class T>
T parse_choice(const std::string& flag, const std::string& text, std::optional<T> parsed,
               const char* choices, FirstProblem& problem) {
  if (!parsed) problem.add(fmt::format("{} '{}': expected one of {}", flag, text, choices));
  return parsed.value_or(T{});
}

/// Notes the frame limits of render/renderer.h that no single flag's range can hold (each
/// flag's own range is checked as it is parsed), worded with the flags that set them.
void check_frame_size(const RenderRequest& a, FirstProblem& problem) {
  const long long pixels = static_cast<long long>(a.width) * a.height;
  if (pixels > kMaxImagePixels) {
    problem.add(fmt::format("--width {} x --height {} is {} pixels; at most {} are rendered",
                            a.width, a.height, pixels, kMaxImagePixels));
    return;
  }
  const long long samples = pixels * a.ssaa * a.ssaa;
  if (samples > kMaxImageSamples) {
    problem.add(
        fmt::format("--width {} x --height {} at --ssaa {} is {} samples; at most {} are "
                    "rendered (lower --ssaa or the size)",
                    a.width, a.height, a.ssaa, samples, kMaxImageSamples));
  }
}

}  // namespace

Result<RenderOptions> make_render_options(const RenderRequest& a, const Plan& plan) {
  FirstProblem problem;
  check_frame_size(a, problem);
  const Projection projection = parse_choice<Projection>(
      "--projection", a.projection,
      a.projection == "perspective"    ? std::optional(Projection::perspective)
      : a.projection == "orthographic" ? std::optional(Projection::orthographic)
                                       : std::nullopt,
      "perspective, orthographic", problem);
  RenderOptions o{.width = a.width, .height = a.height};
  o.camera = chosen_camera(a, plan, projection, problem);
  if (!a.view.empty()) {
    o.view = parse_choice("--view", a.view, parse_view_preset(a.view),
                          "front, back, left, right, top, iso", problem);
  }
  o.view_projection = projection;
  o.view_fov_deg = a.fov;
  o.shading = parse_choice("--shading", a.shading, parse_shading_mode(a.shading),
                           "unlit, flat, gouraud, phong", problem);
  o.shadows = parse_choice<ShadowFilter>("--shadows", a.shadows,
                                         a.shadows == "off"    ? std::optional(ShadowFilter::off)
                                         : a.shadows == "hard" ? std::optional(ShadowFilter::hard)
                                         : a.shadows == "pcf"  ? std::optional(ShadowFilter::pcf)
                                                               : std::nullopt,
                                         "off, hard, pcf", problem);
  o.shadow_resolution = a.shadow_res;
  o.ssaa = a.ssaa;
  o.background =
      parse_choice("--background", a.background, parse_color(a.background), "#rrggbb", problem);
  if (a.grid != "on" && a.grid != "off")
    problem.add(fmt::format("--grid '{}': expected on or off", a.grid));
  o.grid = GridLines{.enabled = a.grid == "on",
                     .origin = {plan.site.origin.x, plan.site.origin.y},
                     .cell_size = plan.site.cell_size,
                     .cells = plan.site.cells};
  o.lights = plan.lights;
  if (a.sun) {
    o.lights = {sun_and_sky_light(*a.sun)};
    o.outdoors = a.sun->z > 0 ? Outdoors{.obstructions = plan.obstructions}
                              : night_outdoors(plan.obstructions);
  }
  const Result<Parts> parts = parse_parts(a.parts);
  if (parts) o.parts = parts.value();
  else problem.add(parts.message());
  o.threads = a.threads;
  o.outputs = FrameOutputs{.depth = false, .object_ids = false};
  o.cull = parse_choice<FaceCull>("--cull", a.cull,
                                  a.cull == "visibility" ? std::optional(FaceCull::visibility)
                                  : a.cull == "portals"  ? std::optional(FaceCull::portals)
                                  : a.cull == "none"     ? std::optional(FaceCull::none)
                                  : a.cull == "back"     ? std::optional(FaceCull::back_faces)
                                                         : std::nullopt,
                                  "none, back, portals, visibility", problem);
  if (a.frustum_cull != "on" && a.frustum_cull != "off")
    problem.add(fmt::format("--frustum-cull '{}': expected on or off", a.frustum_cull));
  o.cull_frustum = a.frustum_cull == "on";
  if (problem.found()) return problem.error();
  if (const Status checked = check_render_options(o); !checked) {
    Error error = checked.error();
    error.message = "render: " + error.message;
    return error;
  }
  return o;
}

}  // namespace roomcad
