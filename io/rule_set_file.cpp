// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/rule_set_file.h"

#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/text_file.h"

namespace roomcad {

Result<RuleSet> load_rule_set(const std::string& name_or_file, std::string_view argument) {
  if (std::optional<RuleSet> builtin = builtin_rule_set(name_or_file)) return *builtin;
  std::error_code ec;
  if (!std::filesystem::exists(name_or_file, ec))
    return Error{Code::usage_error,
                 fmt::format("{} \"{}\": neither a rule set ({}) nor a rules file", argument,
                             name_or_file, fmt::join(builtin_rule_set_names(), ", "))};
  const Result<std::string> text = read_text_file(name_or_file);
  if (!text) return text.error();
  return parse_rule_set(text.value(), name_or_file);
}

}  // namespace roomcad
