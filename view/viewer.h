// SPDX-License-Identifier: GPL-3.0-or-later
// The window's state and behaviour without the window: a session (the plan being edited), a
// camera, display toggles and the frame they give. The SDL glue (view/sdl_window.h) only feeds
// it inputs and shows its frames, so everything the window does is tested headless here.
//
// A frame is roomcad's own renderer (render/renderer.h) drawing the plan's model with the
// objects named by validation errors in red and the selection tinted blue, then the wireframe
// and the text overlay when they are on. Without a selection, errors, wireframe and overlay, a
// frame is pixel for pixel what `roomcad render` draws with the same camera and options.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "render/scene.h"
#include "solid/build_model.h"
#include "view/frame_overlay.h"
#include "view/input.h"
#include "view/key_bindings.h"
#include "view/model_cache.h"
#include "view/view_session.h"

namespace roomcad {

struct ViewerOptions {
  int width = 1280;  ///< frame pixels, as RenderOptions
  int height = 720;
  std::optional<Camera> camera{};     ///< nullopt: frame the model from `view`
  ViewPreset view = ViewPreset::iso;  ///< perspective, 50 degrees, as `roomcad render --view`
  bool overlay = true;                ///< text on the frame (toggled with 'o')
  int threads = 0;                    ///< render threads, 0: all cores
  std::string level{};                ///< show only this level at start; empty: all
};

/// Colours of the highlights.
inline constexpr Color kErrorColor{0xdc, 0x1e, 0x1e};
inline constexpr Color kSelectionTint{0x3c, 0x8c, 0xff};

class Viewer {
 public:
  /// Builds the model of the session's plan and frames it.
  /// @pre options.width and height in 1 .. kMaxImageSide (check_render_options).
  Viewer(ViewSession session, const ViewerOptions& options);

  /// Applies one input: a bound key's action, a click (selects what the pixel shows, or
  /// nothing), a drag (orbit; right button: pan) or wheel notches (zoom). A wait does nothing
  /// here: the window does the waiting (run_window).
  /// @return false when the input asks to quit.
  bool handle(const InputEvent& input);
  /// Looks at the plan's file (ViewSession::reload_if_changed): reloads it, or shows the
  /// conflict with the window's unsaved edits. @return true if it found a change (the frame
  /// will be drawn again).
  bool poll_file();
  /// @return the current frame, drawn again only if something changed since the last call.
  /// Cost: one render_scene (see render/renderer.h) when anything changed, else O(1).
  const RgbImage& frame();
  /// @return true when the next frame() will draw.
  [[nodiscard]] bool needs_redraw() const { return dirty_; }

  [[nodiscard]] const Camera& camera() const { return camera_; }
  [[nodiscard]] const RenderOptions& render_options() const { return options_; }
  [[nodiscard]] const ViewSession& session() const { return session_; }
  /// Milliseconds the last drawn frame took: highlight, render and wireframe (not the
  /// overlay, which shows this number, nor the model rebuild).
  [[nodiscard]] double last_frame_ms() const { return frame_ms_; }
  /// Milliseconds the model rebuild before the last frame took (0 if the plan had not changed).
  [[nodiscard]] double last_build_ms() const { return build_ms_; }
  /// What the last model rebuild built and reused (view/model_cache.h).
  [[nodiscard]] const ModelCacheStats& last_build_stats() const { return models_.last_stats(); }

 private:
  void rebuild_model();
  void apply(Action action);
  void apply_camera(Action action);
  /// The camera moves of walking, for the actions that have one. @return whether it had one.
  bool apply_walk(Action action);
  [[nodiscard]] double floor_height() const;
  void add_cells();
  void apply_display(Action action);
  void apply_edit(Action action);
  void step(int dx, int dy);
  void step_level(int by);
  void frame_preset(ViewPreset preset);
  void pick(int x, int y);
  void draw();
  void highlight();
  [[nodiscard]] OverlayText overlay_text() const;

  ViewSession session_;
  ViewerOptions viewer_options_;
  RenderOptions options_;
  Camera camera_;
  ModelCache models_;  ///< rebuilds only the wall groups an edit touched
  Scene scene_;
  Plan drawn_plan_;  ///< the plan (or level) scene_ shows
  /// The scene revision whose cells were looked for: found once the eye first stands inside
  /// the model, for the portal walk (an edit makes a new scene, which looks again).
  std::uint64_t cells_revision_ = 0;
  std::vector<Color> base_colors_;    ///< scene_ colours before highlighting
  std::vector<std::string> objects_;  ///< Model::objects of the model drawn
  std::uint64_t built_revision_ = ~std::uint64_t{0};
  std::string model_problem_;  ///< why the last rebuild failed, or ""
  FrameBuffers buffers_;
  RgbImage shown_;     ///< the colour buffer with wireframe and overlay
  std::string level_;  ///< the level shown alone (plan_of_level), or "" for all
  bool wireframe_ = false;
  bool walking_ = false;  ///< first person (Action::toggle_walk), else orbiting
  bool dirty_ = true;
  double frame_ms_ = 0.0;
  double build_ms_ = 0.0;
};

}  // namespace roomcad
