// SPDX-License-Identifier: GPL-3.0-or-later
// The rule set a caller asks for by name: a built-in set or a rules file (roomcad validate and
// draw --rules, the Python module's Plan.validate(rules=...)).
#pragma once

#include <string>
#include <string_view>

#include "core/error.h"
#include "validation/rule_set.h"

namespace roomcad {

/// @param[in] name_or_file  a built-in set's name (default, accessibility, all) or a rules
///                          file's path (JSON, validation/rule_set.h)
/// @param[in] argument      how the caller's user passed it, for messages ("--rules")
/// @return the set; a usage_error naming the argument and value for neither a set nor a
///         file, naming the file, field and value for a bad file; an io_error for a file
///         that cannot be read.
[[nodiscard]] Result<RuleSet> load_rule_set(const std::string& name_or_file,
                                            std::string_view argument);

}  // namespace roomcad
