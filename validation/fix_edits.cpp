// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/fix_edits.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "plan/plan_edit.h"
#include "plan/value_text.h"

namespace roomcad {
namespace {

/// Quotes a command-line word when the shell would split or expand it.
std::string shell_word(std::string_view word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("-_./,:=#+").find(c) != std::string_view::npos;
  });
  if (plain) return std::string(word);
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + '\'';
}

/// set_field, whose refusal breaks apply_fix_edits' precondition.
void set_or_throw(Plan& plan, const std::string& id, const std::string& key,
                  const std::string& value, std::string_view verb) {
  if (const Result<EditSummary> set = set_field(plan, id, key, value, verb); !set)
    throw PreconditionError(set.error());
}

void apply_add(Plan& plan, const FixEdit& edit) {
  const auto field = [&](std::string_view key) -> const std::string* {
    for (const auto& [k, v] : edit.fields)
      if (k == key) return &v;
    return nullptr;
  };
  const std::string* type = field("type");
  const std::optional<OpeningType> kind = type ? parse_enum<OpeningType>(*type) : std::nullopt;
  if (!kind || !field("wall"))
    throw PreconditionError("apply_fix_edits: an add edit needs a door or window type and a wall",
                            Code::precondition);
  Opening o = default_opening(*kind);
  o.id = edit.id;
  o.wall = *field("wall");
  add_opening(plan, o);
  for (const auto& [key, value] : edit.fields)
    if (key != "type" && key != "wall") set_or_throw(plan, edit.id, key, value, "add");
}

}  // namespace

void apply_fix_edits(Plan& plan, const std::vector<FixEdit>& edits) {
  for (const FixEdit& edit : edits) {
    switch (edit.op) {
      case FixEdit::Op::set:
        for (const auto& [key, value] : edit.fields) set_or_throw(plan, edit.id, key, value, "set");
        break;
      case FixEdit::Op::add: apply_add(plan, edit); break;
      case FixEdit::Op::remove:
        remove_object(plan, edit.id, RemoveOptions{.cascade = edit.cascade});
        break;
    }
  }
}

std::string edit_command(const FixEdit& edit, std::string_view plan_file) {
  const std::string plan = shell_word(plan_file);
  switch (edit.op) {
    case FixEdit::Op::set: {
      std::string out = fmt::format("roomcad set {} {}", plan, shell_word(edit.id));
      for (const auto& [key, value] : edit.fields) out += ' ' + shell_word(key + '=' + value);
      return out;
    }
    case FixEdit::Op::add: {
      std::string kind = "door";
      std::string options;
      for (const auto& [key, value] : edit.fields) {
        if (key == "type") kind = value;
        else options += fmt::format(" --{} {}", key, shell_word(value));
      }
      return fmt::format("roomcad add {} {} --id {}{}", plan, kind, shell_word(edit.id), options);
    }
    case FixEdit::Op::remove:
      return fmt::format("roomcad rm {} {}{}", plan, shell_word(edit.id),
                         edit.cascade ? " --cascade" : "");
  }
  return {};
}

}  // namespace roomcad
