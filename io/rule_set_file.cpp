// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/rule_loading.h"

#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/text_file.h"

namespace roomcad::cli {

Result<RuleSet> load_rule_set(const std::string& name_or_file) {
  if (std::optional<RuleSet> builtin = builtin_rule_set(name_or_file)) return *builtin;
  std::error_code ec;
  if (!std::filesystem::exists(name_or_file, ec))
    return Error{Code::usage_error,
                 fmt::format("--rules \"{}\": neither a rule set ({}) nor a rules file", name_or_file,
                             fmt::join(builtin_rule_set_names(), ", "))};
  const Result<std::string> text = read_text_file(name_or_file);
  if (!text) return text.error();
  return parse_rule_set(text.value(), name_or_file);
}

}  // namespace roomcad::cli
