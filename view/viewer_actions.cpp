// SPDX-License-Identifier: GPL-3.0-or-later
// What each key's action does to the viewer: camera moves, display toggles and edits.
#include <algorithm>

#include <fmt/format.h>

#include "plan/plan_levels.h"
#include "validation/report_format.h"
#include "view/orbit_camera.h"
#include "view/viewer.h"
#include "view/walk_camera.h"

namespace roomcad {
namespace {

constexpr double kKeyDegrees = 15.0;  ///< one orbit or turn key press
constexpr double kPanStep = 0.1;      ///< one pan key press, of the visible height
constexpr double kZoomStep = 0.8;     ///< one zoom key press
constexpr double kWalkStep = 0.5;     ///< one step forward or back, metres

ShadingMode next_mode(ShadingMode m) {
  switch (m) {
    case ShadingMode::phong: return ShadingMode::flat;
    case ShadingMode::flat: return ShadingMode::gouraud;
    case ShadingMode::gouraud: return ShadingMode::unlit;
    case ShadingMode::unlit: return ShadingMode::phong;
  }
  return ShadingMode::phong;
}

std::string_view to_text(ShadingMode m) {
  switch (m) {
    case ShadingMode::phong: return "phong";
    case ShadingMode::flat: return "flat";
    case ShadingMode::gouraud: return "gouraud";
    case ShadingMode::unlit: return "unlit";
  }
  return "";
}

/// The world axis (and sign) an axis-turn action turns about, or a zero vector.
glm::dvec3 turn_axis(Action a) {
  switch (a) {
    case Action::turn_x: return {1, 0, 0};
    case Action::turn_x_back: return {-1, 0, 0};
    case Action::turn_y: return {0, 1, 0};
    case Action::turn_y_back: return {0, -1, 0};
    case Action::turn_z: return {0, 0, 1};
    case Action::turn_z_back: return {0, 0, -1};
    default: return {0, 0, 0};
  }
}

}  // namespace

void Viewer::apply(Action action) {
  if (action >= Action::orbit_left && action <= Action::toggle_walk) apply_camera(action);
  else if (action >= Action::toggle_shadows && action <= Action::toggle_overlay)
    apply_display(action);
  else apply_edit(action);
}

double Viewer::floor_height() const {
  const Plan& plan = session_.plan();
  if (const Level* shown = level_.empty() ? nullptr : find_level(plan, level_))
    return shown->elevation;
  double lowest = 0.0;
  for (std::size_t i = 0; i < plan.levels.size(); ++i)
    lowest = i == 0 ? plan.levels[i].elevation : std::min(lowest, plan.levels[i].elevation);
  return lowest;
}

bool Viewer::apply_walk(Action a) {
  switch (a) {
    case Action::orbit_left: camera_ = look_around(camera_, kKeyDegrees, 0.0); return true;
    case Action::orbit_right: camera_ = look_around(camera_, -kKeyDegrees, 0.0); return true;
    case Action::orbit_up: camera_ = walk_forward(camera_, kWalkStep); return true;
    case Action::orbit_down: camera_ = walk_forward(camera_, -kWalkStep); return true;
    case Action::zoom_in: camera_ = walk_forward(camera_, kWalkStep); return true;
    case Action::zoom_out: camera_ = walk_forward(camera_, -kWalkStep); return true;
    default: return false;
  }
}

void Viewer::apply_camera(Action a) {
  if (a == Action::toggle_walk) {
    walking_ = !walking_;
    if (walking_) camera_ = stand_at_target(camera_, floor_height());
    return;
  }
  if (walking_ && apply_walk(a)) return;
  if (a >= Action::view_top && a <= Action::view_iso) walking_ = false;
  const glm::dvec3 axis = turn_axis(a);
  if (glm::length(axis) > 0.0) camera_ = rotate_camera(camera_, axis, kKeyDegrees);
  switch (a) {
    case Action::orbit_left: camera_ = orbit_camera(camera_, -kKeyDegrees, 0.0); break;
    case Action::orbit_right: camera_ = orbit_camera(camera_, kKeyDegrees, 0.0); break;
    case Action::orbit_up: camera_ = orbit_camera(camera_, 0.0, kKeyDegrees); break;
    case Action::orbit_down: camera_ = orbit_camera(camera_, 0.0, -kKeyDegrees); break;
    case Action::pan_left: camera_ = pan_camera(camera_, -kPanStep, 0.0); break;
    case Action::pan_right: camera_ = pan_camera(camera_, kPanStep, 0.0); break;
    case Action::pan_up: camera_ = pan_camera(camera_, 0.0, kPanStep); break;
    case Action::pan_down: camera_ = pan_camera(camera_, 0.0, -kPanStep); break;
    case Action::zoom_in: camera_ = zoom_camera(camera_, kZoomStep); break;
    case Action::zoom_out: camera_ = zoom_camera(camera_, 1.0 / kZoomStep); break;
    case Action::view_top: frame_preset(ViewPreset::top); break;
    case Action::view_front: frame_preset(ViewPreset::front); break;
    case Action::view_side: frame_preset(ViewPreset::right); break;
    case Action::view_iso: frame_preset(ViewPreset::iso); break;
    case Action::toggle_projection: camera_ = toggle_projection(camera_); break;
    default: break;
  }
}

void Viewer::apply_display(Action a) {
  switch (a) {
    case Action::toggle_shadows:
      options_.shadows =
          options_.shadows == ShadowFilter::off ? ShadowFilter::pcf : ShadowFilter::off;
      break;
    case Action::next_shading: options_.shading = next_mode(options_.shading); break;
    case Action::toggle_grid: options_.grid.enabled = !options_.grid.enabled; break;
    case Action::toggle_wireframe: wireframe_ = !wireframe_; break;
    case Action::toggle_overlay: viewer_options_.overlay = !viewer_options_.overlay; break;
    case Action::next_level: step_level(1); break;
    case Action::previous_level: step_level(-1); break;
    default: break;
  }
}

namespace {
/// The outcome of an action reaches the window as the session's message(); the Status each
/// returns is for programs that drive a session (and the tests).
void shown(const Status&) {}
}  // namespace

void Viewer::step(int dx, int dy) {
  if (session_.selected()) shown(session_.move_selection(dx, dy));
  else camera_ = pan_camera(camera_, dx * kPanStep, dy * kPanStep);
}

void Viewer::apply_edit(Action a) {
  switch (a) {
    case Action::step_west: step(-1, 0); break;
    case Action::step_east: step(1, 0); break;
    case Action::step_north: step(0, 1); break;
    case Action::step_south: step(0, -1); break;
    case Action::select_next: session_.select_next(); break;
    case Action::deselect: session_.select(std::nullopt); break;
    case Action::turn_selection: shown(session_.rotate_selection(90.0)); break;
    case Action::turn_selection_back: shown(session_.rotate_selection(-90.0)); break;
    case Action::delete_selection: shown(session_.delete_selection()); break;
    case Action::save: shown(session_.save()); break;
    case Action::undo: shown(session_.undo()); break;
    case Action::reload_file: shown(session_.reload_file()); break;
    case Action::keep_window_version: shown(session_.keep_window_version()); break;
    default: break;
  }
}

/// Levels in the order the keys step through them: all (-1), then each level from the lowest
/// (by elevation, then as listed), then all again.
void Viewer::step_level(int by) {
  const std::vector<Level>& levels = session_.plan().levels;
  if (levels.empty()) return;
  std::vector<std::size_t> order(levels.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return levels[a].elevation < levels[b].elevation;
  });
  const auto n = static_cast<int>(order.size());
  int at = -1;  // all levels
  for (int i = 0; i < n; ++i)
    if (levels[order[i]].id == level_) at = i;
  at = ((at + 1 + by) % (n + 1) + n + 1) % (n + 1) - 1;
  level_ = at < 0 ? std::string() : levels[order[at]].id;
  built_revision_ = ~std::uint64_t{0};  // rebuild the model of what is shown
}

OverlayText Viewer::overlay_text() const {
  OverlayText t;
  const ViewSession& s = session_;
  t.status.push_back(fmt::format(
      "{}{}  {}{}", s.path().filename().string(), s.is_modified() ? " (modified)" : "",
      format_report_summary(s.report()), level_.empty() ? "" : fmt::format("  level {}", level_)));
  t.status.push_back(fmt::format(
      "{}  {} shading  shadows {}  frame {:.1f} ms{}", to_string(camera_.projection),
      to_text(options_.shading), options_.shadows == ShadowFilter::off ? "off" : "on", frame_ms_,
      build_ms_ > 0.0 ? fmt::format(" (model rebuilt in {:.0f} ms)", build_ms_) : std::string()));
  if (!model_problem_.empty()) t.status.push_back(model_problem_);
  t.message = s.message();
  t.selection = s.selection_properties();
  for (const Diagnostic& d : s.report().items)
    if (d.severity == Severity::error)
      t.errors.push_back(fmt::format("error[{}] {}: {}", to_string(d.code),
                                     fmt::join(d.objects, ", "), d.message));
  t.help =
      "a/d/w/s orbit  x/y/z turn  shift+arrows pan  +/- zoom  1-4 views  p proj  h shadows  "
      "m shading  g grid  e wire  l level  o text  click select  arrows move  r turn  del delete  "
      "ctrl+s save  ctrl+z undo  ctrl+r reload  ctrl+k keep yours  q quit";
  return t;
}

}  // namespace roomcad
