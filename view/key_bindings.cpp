// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/key_bindings.h"

#include <array>

#include <fmt/format.h>

namespace roomcad {
namespace {

using A = Action;
constexpr std::array kBindings{
    KeyBinding{"a", false, false, A::orbit_left, "orbit left (15 degrees about the target)"},
    KeyBinding{"d", false, false, A::orbit_right, "orbit right"},
    KeyBinding{"w", false, false, A::orbit_up, "orbit up"},
    KeyBinding{"s", false, false, A::orbit_down, "orbit down"},
    KeyBinding{"x", false, false, A::turn_x, "turn the view 15 degrees about the world x axis"},
    KeyBinding{"x", false, true, A::turn_x_back, "the same, backwards"},
    KeyBinding{"y", false, false, A::turn_y, "turn about the world y axis"},
    KeyBinding{"y", false, true, A::turn_y_back, "the same, backwards"},
    KeyBinding{"z", false, false, A::turn_z, "turn about the world z axis"},
    KeyBinding{"z", false, true, A::turn_z_back, "the same, backwards"},
    KeyBinding{"left", false, true, A::pan_left, "pan left (a tenth of the view)"},
    KeyBinding{"right", false, true, A::pan_right, "pan right"},
    KeyBinding{"up", false, true, A::pan_up, "pan up"},
    KeyBinding{"down", false, true, A::pan_down, "pan down"},
    KeyBinding{"plus", false, false, A::zoom_in, "zoom in (also the wheel)"},
    KeyBinding{"minus", false, false, A::zoom_out, "zoom out"},
    KeyBinding{"1", false, false, A::view_top, "view from the top"},
    KeyBinding{"2", false, false, A::view_front, "view from the front (south)"},
    KeyBinding{"3", false, false, A::view_side, "view from the side (east)"},
    KeyBinding{"4", false, false, A::view_iso, "iso view (south-west, above)"},
    KeyBinding{"p", false, false, A::toggle_projection, "perspective / parallel projection"},
    KeyBinding{"f", false, false, A::toggle_walk,
               "walk in the first person from where the view looks (eye 1.6 m over the floor): "
               "w and s step, a and d turn, dragging looks around; f again, or a view key, "
               "orbits again"},
    KeyBinding{"h", false, false, A::toggle_shadows, "shadows on / off"},
    KeyBinding{"m", false, false, A::next_shading, "shading: phong, flat, gouraud, unlit"},
    KeyBinding{"g", false, false, A::toggle_grid, "site grid on / off"},
    KeyBinding{"e", false, false, A::toggle_wireframe, "wireframe (triangle edges) on / off"},
    KeyBinding{"l", false, false, A::next_level,
               "show the next level alone (lowest first), after the last all levels again"},
    KeyBinding{"l", false, true, A::previous_level, "show the previous level alone"},
    KeyBinding{"o", false, false, A::toggle_overlay, "text overlay on / off"},
    KeyBinding{"left", false, false, A::step_west,
               "move the selection a cell west (no selection: pan)"},
    KeyBinding{"right", false, false, A::step_east, "move the selection a cell east"},
    KeyBinding{"up", false, false, A::step_north, "move the selection a cell north"},
    KeyBinding{"down", false, false, A::step_south, "move the selection a cell south"},
    KeyBinding{"tab", false, false, A::select_next, "select the next object"},
    KeyBinding{"escape", false, false, A::deselect, "select nothing"},
    KeyBinding{"r", false, false, A::turn_selection,
               "turn the selection 90 degrees counter-clockwise"},
    KeyBinding{"r", false, true, A::turn_selection_back, "turn the selection 90 degrees clockwise"},
    KeyBinding{"delete", false, false, A::delete_selection,
               "delete the selection (a wall with openings: press twice)"},
    KeyBinding{"backspace", false, false, A::delete_selection, "the same as delete"},
    KeyBinding{"s", true, false, A::save,
               "save (validated; refused while the plan has errors, and if the file changed on "
               "disk meanwhile: then the conflict's choices are shown)"},
    KeyBinding{"z", true, false, A::undo, "undo"},
    KeyBinding{"r", true, false, A::reload_file,
               "reload the file, dropping unsaved edits (Ctrl+Z brings them back); in a "
               "conflict: take the file's version"},
    KeyBinding{"k", true, false, A::keep_window_version,
               "in a conflict: keep the window's version, saving it over the file"},
    KeyBinding{"q", false, false, A::quit, "quit"},
};

}  // namespace

std::span<const KeyBinding> key_bindings() { return kBindings; }

std::optional<Action> action_for(const InputEvent& key) {
  if (key.type != InputEvent::Type::key) return std::nullopt;
  for (const KeyBinding& b : kBindings)
    if (b.key == key.key && b.ctrl == key.ctrl && b.shift == key.shift) return b.action;
  return std::nullopt;
}

std::string key_help() {
  std::string text;
  for (const KeyBinding& b : kBindings) {
    const std::string keys =
        fmt::format("{}{}{}", b.ctrl ? "ctrl+" : "", b.shift ? "shift+" : "", b.key);
    text += fmt::format("  {:<15} {}\n", keys, b.help);
  }
  text +=
      "  mouse: click selects, left drag orbits, right drag pans, wheel zooms;\n"
      "  the window reloads the plan when its file changes on disk; if it changes while the\n"
      "  window has unsaved edits (or Ctrl+S finds it changed), nothing is saved or dropped until\n"
      "  Ctrl+R (take the file's version) or Ctrl+K (keep the window's) is pressed\n";
  return text;
}

}  // namespace roomcad
