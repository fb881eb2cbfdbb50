// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/viewer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <utility>

#include <fmt/format.h>

#include "plan/plan_levels.h"
#include "render/scene_cells.h"
#include "solid/build_model.h"
#include "view/frame_overlay.h"
#include "view/orbit_camera.h"
#include "view/walk_camera.h"
#include "view/wireframe.h"

namespace roomcad {
namespace {

/// Degrees of orbit per pixel dragged, and the zoom factor per wheel notch.
constexpr double kDragDegreesPerPixel = 0.3;
constexpr double kWheelZoom = 0.9;

bool is_inside(const Box3& b, const Vec3& p) {
  return p.x >= b.low[0] && p.x <= b.high[0] && p.y >= b.low[1] && p.y <= b.high[1] &&
         p.z >= b.low[2] && p.z <= b.high[2];
}

Box3 framing_bounds(const Scene& scene) {
  Box3 b = scene.bounds;
  if (is_empty(b))
    add_point(b, glm::dvec3(0.0));  // nothing to frame: look at the origin, as render does
  return b;
}

}  // namespace

Viewer::Viewer(ViewSession session, const ViewerOptions& options)
    : session_(std::move(session)), viewer_options_(options), level_(options.level) {
  options_ =
      RenderOptions{.width = options.width, .height = options.height, .threads = options.threads};
  options_.grid.enabled = true;       // as `roomcad render --grid on`
  options_.outputs.depth = false;     // the window picks by object id, never by depth
  options_.cull = FaceCull::portals;  // from inside a room, only what its doors let through
  options_.reuse_shadow_maps = true;  // the camera moves; the model and lights mostly do not
  rebuild_model();
  if (options.camera) camera_ = *options.camera;
  else frame_preset(options.view);
}

void Viewer::rebuild_model() {
  if (built_revision_ == session_.revision()) return;
  built_revision_ = session_.revision();
  // The level shown alone; a level that an edit or reload removed shows all levels again.
  if (!level_.empty() && !find_level(session_.plan(), level_)) level_.clear();
  const Plan plan = level_.empty() ? session_.plan() : plan_of_level(session_.plan(), level_);
  options_.lights = plan.lights;
  options_.grid = GridLines{.enabled = options_.grid.enabled,
                            .origin = {plan.site.origin.x, plan.site.origin.y},
                            .cell_size = plan.site.cell_size,
                            .cells = plan.site.cells};
  try {
    BuildOptions build;
    build.threads = viewer_options_.threads;
    const Model model = models_.build(plan, build);
    scene_ = flatten_model(model);
    drawn_plan_ = plan;
    objects_ = model.objects;
    base_colors_ = scene_.colors;
    model_problem_.clear();
  } catch (const std::exception& e) {  // keep drawing the last model that could be built
    model_problem_ = fmt::format("model not rebuilt: {}", e.what());
  }
  dirty_ = true;
}

void Viewer::frame_preset(ViewPreset preset) {
  const double aspect = static_cast<double>(options_.width) / options_.height;
  camera_ = frame_view(framing_bounds(scene_), preset, camera_.projection, camera_.fov_deg, aspect);
  dirty_ = true;
}

bool Viewer::handle(const InputEvent& input) {
  switch (input.type) {
    case InputEvent::Type::click: pick(input.x, input.y); break;
    case InputEvent::Type::wheel:
      camera_ = walking_ ? walk_forward(camera_, 0.5 * input.x)
                         : zoom_camera(camera_, std::pow(kWheelZoom, input.x));
      break;
    case InputEvent::Type::drag:
      if (walking_)
        camera_ =
            look_around(camera_, -input.x * kDragDegreesPerPixel, -input.y * kDragDegreesPerPixel);
      else
        camera_ = input.right_button ? pan_camera(camera_, -input.x / double(options_.height),
                                                  input.y / double(options_.height))
                                     : orbit_camera(camera_, -input.x * kDragDegreesPerPixel,
                                                    input.y * kDragDegreesPerPixel);
      break;
    case InputEvent::Type::wait_change: return true;  // the window waits (view/sdl_window.h)
    case InputEvent::Type::key: {
      const std::optional<Action> action = action_for(input);
      if (!action) return true;
      if (*action == Action::quit) return false;
      apply(*action);
      break;
    }
  }
  dirty_ = true;
  return true;
}

bool Viewer::poll_file() {
  const std::uint64_t messages = session_.message_count();
  static_cast<void>(session_.reload_if_changed());         // what it found is a message
  if (session_.message_count() == messages) return false;  // every change found says so
  dirty_ = true;
  return true;
}

void Viewer::pick(int x, int y) {
  frame();  // the id buffer of what is on screen now
  const ObjectIdImage& ids = buffers_.objects;
  if (x < 0 || y < 0 || x >= ids.width || y >= ids.height) return;
  const std::int32_t index = ids.at(x, y);
  session_.select(index >= 0 && static_cast<std::size_t>(index) < objects_.size()
                      ? std::optional<std::string>(objects_[index])
                      : std::nullopt);
}

void Viewer::highlight() {
  std::vector<std::uint8_t> state(objects_.size(), 0);  // 1 error, 2 selected
  const std::vector<std::string> errors = session_.error_objects();
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (std::binary_search(errors.begin(), errors.end(), objects_[i])) state[i] = 1;
    if (session_.selected() == objects_[i]) state[i] = 2;
  }
  scene_.colors = base_colors_;
  for (std::size_t t = 0; t < scene_.objects.size(); ++t) {
    const std::int32_t o = scene_.objects[t];
    if (o < 0 || static_cast<std::size_t>(o) >= state.size() || state[o] == 0) continue;
    Color& c = scene_.colors[t];
    c = state[o] == 1 ? kErrorColor
                      : Color{static_cast<std::uint8_t>((c.r + kSelectionTint.r) / 2),
                              static_cast<std::uint8_t>((c.g + kSelectionTint.g) / 2),
                              static_cast<std::uint8_t>((c.b + kSelectionTint.b) / 2)};
  }
}

void Viewer::draw() {
  const auto rebuild_start = std::chrono::steady_clock::now();
  const bool rebuilt = built_revision_ != session_.revision();
  rebuild_model();
  const auto start = std::chrono::steady_clock::now();
  build_ms_ =
      rebuilt ? std::chrono::duration<double, std::milli>(start - rebuild_start).count() : 0.0;
  highlight();
  if (scene_.revision != cells_revision_ && is_inside(scene_.bounds, camera_.eye)) add_cells();
  options_.camera = camera_;
  render_scene(scene_, options_, buffers_);
  shown_ = buffers_.color;
  if (wireframe_) draw_wireframe(shown_, scene_, frame_camera(scene_, options_));
  // Measured before the overlay, which shows it (the text itself costs well under 1%).
  frame_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // A conflict's choices are shown even with the overlay off: they must not go unseen.
  if (viewer_options_.overlay || session_.in_conflict()) draw_overlay(shown_, overlay_text());
}

void Viewer::add_cells() {
  cells_revision_ = scene_.revision;  // tried once per model, found or not
  try {
    scene_.cells =
        std::make_shared<const SceneCells>(index_cells(find_model_cells(drawn_plan_), scene_));
  } catch (const std::exception&) {  // a wall the build could not make either: draw it all
  }
}

const RgbImage& Viewer::frame() {
  if (dirty_ || built_revision_ != session_.revision()) draw();
  dirty_ = false;
  return shown_;
}

}  // namespace roomcad
