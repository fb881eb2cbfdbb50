// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/render_request.h"

#include <optional>
#include <string>

#include <fmt/format.h>

#include "modeling/build_model.h"
#include "modeling/value_text.h"

namespace roomcad {
namespace {

[[noreturn]] void throw_usage(std::string message) {
  throw PreconditionError(std::move(message), Code::usage_error);
}

/// @return the flag's value as x,y,z. @throws PreconditionError (usage_error) naming it.
Vec3 require_vec3(const std::string& flag, const std::string& text) {
  if (const std::optional<Vec3> v = parse_vec3(text)) return *v;
  throw_usage(fmt::format("{} '{}': expected three finite numbers x,y,z (metres)", flag, text));
}

/// The camera the flags ask for, or nullopt to frame the model from a preset.
std::optional<Camera> chosen_camera(const RenderRequest& a, const Plan& plan, Projection projection) {
  if (!a.camera.empty()) {
    for (const Camera& c : plan.cameras)
      if (c.id == a.camera) return c;
    std::string known;
    for (const Camera& c : plan.cameras) known += (known.empty() ? "" : ", ") + c.id;
    throw_usage(fmt::format("--camera '{}': the plan has no such camera (it has: {})", a.camera,
                              known.empty() ? "none" : known));
  }
  if (a.eye.empty() != a.target.empty()) {
    throw_usage("--eye and --target go together: give both or neither");
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
  if (c.eye == c.target) throw_usage(fmt::format("--eye and --target are both '{}'", a.eye));
  return c;
}

template <class T>
T parse_choice(const std::string& flag, const std::string& text, std::optional<T> parsed,
               const char* choices) {
  if (!parsed) throw_usage(fmt::format("{} '{}': expected one of {}", flag, text, choices));
  return *parsed;
}

/// The frame limits of render/renderer.h that no single flag's range can hold (each flag's own
/// range is checked as it is parsed), worded with the flags that set them.
/// @throws PreconditionError (usage_error) naming the flags, their values and the limit.
void check_frame_size(const RenderRequest& a) {
  const long long pixels = static_cast<long long>(a.width) * a.height;
  if (pixels > kMaxImagePixels) {
    throw_usage(fmt::format("--width {} x --height {} is {} pixels; at most {} are rendered",
                              a.width, a.height, pixels, kMaxImagePixels));
  }
  const long long samples = pixels * a.ssaa * a.ssaa;
  if (samples > kMaxImageSamples) {
    throw_usage(fmt::format("--width {} x --height {} at --ssaa {} is {} samples; at most {} are "
                              "rendered (lower --ssaa or the size)",
                              a.width, a.height, a.ssaa, samples, kMaxImageSamples));
  }
}

}  // namespace

RenderOptions make_render_options(const RenderRequest& a, const Plan& plan) {
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
  if (a.grid != "on" && a.grid != "off") throw_usage(fmt::format("--grid '{}': expected on or off", a.grid));
  o.grid = GridLines{.enabled = a.grid == "on", .origin = {plan.site.origin.x, plan.site.origin.y},
                     .cell_size = plan.site.cell_size, .cells = plan.site.cells};
  o.lights = plan.lights;
  const Result<Parts> parts = parse_parts(a.parts);
  if (!parts) throw PreconditionError(parts.error());
  o.parts = parts.value();
  o.threads = a.threads;
  o.outputs = FrameOutputs{.depth = false, .object_ids = false};
  o.cull = parse_choice<FaceCull>("--cull", a.cull,
                                  a.cull == "visibility" ? std::optional(FaceCull::visibility)
                                  : a.cull == "none"     ? std::optional(FaceCull::none)
                                  : a.cull == "back"     ? std::optional(FaceCull::back_faces)
                                                         : std::nullopt,
                                  "none, back, visibility");
  if (a.frustum_cull != "on" && a.frustum_cull != "off")
    throw_usage(fmt::format("--frustum-cull '{}': expected on or off", a.frustum_cull));
  o.cull_frustum = a.frustum_cull == "on";
  throw_if_failed(check_render_options(o), "render");
  return o;
}

}  // namespace roomcad
