// SPDX-License-Identifier: GPL-3.0-or-later
// The rule set a command is asked for: a built-in name or a rules file (validate, draw).
#pragma once

#include <string>

#include "core/error.h"
#include "validation/rule_set.h"

namespace roomcad::cli {

/// @return the built-in set `name_or_file` (default, accessibility, all) or the rules file of
///         that path, read; a usage_error (exit 2) naming the file, field and value for a bad
///         file, an io_error for one that cannot be read.
[[nodiscard]] Result<RuleSet> load_rule_set(const std::string& name_or_file);

}  // namespace roomcad::cli
