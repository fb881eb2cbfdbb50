// SPDX-License-Identifier: GPL-3.0-or-later
// What the window reacts to, free of SDL: key presses by name, clicks, drags and wheel turns.
// The SDL glue (view/sdl_window.cpp) turns SDL events into these, and `--keys` scripts are
// parsed into the same events, so a script drives exactly what a person at the window does.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace roomcad {

/// One input. Keys are named in lower case: a..z, 0..9, left, right, up, down, delete,
/// backspace, tab, escape, plus, minus.
struct InputEvent {
  /// wait_change, in scripts only: wait until the plan's file changes on disk (another editor
  /// saved it), the window running meanwhile.
  enum class Type { key, click, drag, wheel, wait_change };
  Type type = Type::key;
  std::string key;            ///< Type::key: the key's name
  bool ctrl = false;          ///< Type::key: Ctrl held
  bool shift = false;         ///< Type::key: Shift held
  int x = 0;                  ///< click: pixel column; drag: pixels moved right; wheel: notches up
  int y = 0;                  ///< click: pixel row; drag: pixels moved down
  bool right_button = false;  ///< drag: with the right button (pan) instead of the left (orbit)
  friend bool operator==(const InputEvent&, const InputEvent&) = default;
};

/// @return true if `name` is one of the key names above.
[[nodiscard]] bool is_key_name(std::string_view name);

/// Longest a `wait:change` input waits (kKeyScriptSyntax says it too).
inline constexpr int kWaitChangeSeconds = 60;

/// The syntax of `--keys`, for --help.
inline constexpr std::string_view kKeyScriptSyntax =
    "comma-separated inputs, applied in order: a key name (a..z, 0..9, left, right, up, down, "
    "delete, backspace, tab, escape, plus, minus) with optional ctrl+ "
    "and shift+ prefixes (ctrl+s); click:X:Y (left click at pixel X,Y); drag:DX:DY (left drag "
    "by DX,DY pixels: orbit); pan:DX:DY (right drag); wheel:N (N notches, negative: away); "
    "wait:change (wait, at most 60 s, until the plan file changes on disk)";

/// Parses a `--keys` script, e.g. "1,ctrl+s,click:640:360,drag:-40:0,wheel:2,wait:change".
/// @return the events, or an error naming the item and what is wrong with it. O(length).
[[nodiscard]] Result<std::vector<InputEvent>> parse_key_script(std::string_view script);

}  // namespace roomcad
