// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad view` runs the window's own program, roomcad-view, beside the roomcad executable:
// only it links the window's libraries (SDL and, through it, audio, X11 and Wayland), so that
// every other command starts without loading them.
#pragma once

#include <CLI/CLI.hpp>

namespace roomcad::cli {

/// The window command's name and description, in `roomcad --help` and roomcad-view's own.
inline constexpr const char* kWindowCommand = "view";
inline constexpr const char* kWindowDescription =
    "Open a window on the plan: look around, select, edit, save";
/// The window's program, looked for in the folder of the running roomcad executable.
inline constexpr const char* kWindowProgram = "roomcad-view";

/// @return whether the command line asks for the window (`roomcad view ...`).
[[nodiscard]] bool is_window_command(int argc, char** argv);

/// Replaces this process by roomcad-view with the same arguments (its --help and errors name
/// `roomcad view`). @return only if that fails: 2, having said why (not installed beside
/// roomcad, not executable).
[[nodiscard]] int run_window_program(int argc, char** argv);

/// Lists `view` among roomcad's subcommands (its options are roomcad-view's: `roomcad view
/// --help` shows them).
void add_window_command_entry(CLI::App& root);

}  // namespace roomcad::cli
