// SPDX-License-Identifier: GPL-3.0-or-later
// Which key does what in the window: one table, used to dispatch keys, to print the key help
// (`roomcad view --help`, the overlay) and to document docs/cli.md's table.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "view/input.h"

namespace roomcad {

/// What keys do. Viewer::apply dispatches by range, so camera actions stay between
/// orbit_left and toggle_projection, display toggles between toggle_shadows and toggle_overlay.
enum class Action {
  orbit_left,
  orbit_right,
  orbit_up,
  orbit_down,  // about the target
  turn_x,
  turn_x_back,
  turn_y,
  turn_y_back,
  turn_z,
  turn_z_back,  // about world axes
  pan_left,
  pan_right,
  pan_up,
  pan_down,
  zoom_in,
  zoom_out,
  view_top,
  view_front,
  view_side,
  view_iso,
  toggle_projection,
  toggle_walk,  // first person: a and d turn, w and s step, dragging looks around
  toggle_shadows,
  next_shading,
  toggle_grid,
  toggle_wireframe,
  next_level,
  previous_level,  // show one level alone (plan format version 2), or all
  toggle_overlay,
  step_west,
  step_east,
  step_north,
  step_south,  // move the selection a cell, else pan
  select_next,
  deselect,
  turn_selection,
  turn_selection_back,
  delete_selection,
  save,
  undo,
  reload_file,
  keep_window_version,
  quit,
};

/// One key of the table.
struct KeyBinding {
  std::string_view key;  ///< an InputEvent key name
  bool ctrl = false;
  bool shift = false;
  Action action;
  std::string_view help;
};

/// @return every binding, in the order the help lists them.
[[nodiscard]] std::span<const KeyBinding> key_bindings();

/// @return the action of a key press (modifiers must match), or nullopt for an unbound key.
[[nodiscard]] std::optional<Action> action_for(const InputEvent& key);

/// @return the key help, one "keys  what" line per binding plus the mouse, for --help.
[[nodiscard]] std::string key_help();

}  // namespace roomcad
