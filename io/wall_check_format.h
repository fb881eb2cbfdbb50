// SPDX-License-Identifier: GPL-3.0-or-later
// Printing a WallCheck (solid/wall_check.h): what `roomcad build --check` prints, as text for
// people or one JSON object for tools (the Python module's Model.check() reads the JSON).
#pragma once

#include <string>

#include "solid/wall_check.h"

namespace roomcad {

/// @return one line per check, then "check: ok" or "check: FAILED"; ends with a newline.
[[nodiscard]] std::string format_wall_check_text(const WallCheck& check);

/// @return `{"ok": ..., "vertices": ..., ..., "relative_difference": ...}` and a newline.
[[nodiscard]] std::string format_wall_check_json(const WallCheck& check);

}  // namespace roomcad
