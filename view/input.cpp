// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/input.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <optional>

#include <fmt/format.h>

namespace roomcad {
namespace {

constexpr std::array<std::string_view, 10> kNamedKeys{
    "left", "right", "up", "down", "delete", "backspace", "tab", "escape", "plus", "minus"};

/// @return `text` as an int, or nullopt (no sign other than a leading '-', no spaces).
std::optional<int> parse_int(std::string_view text) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

/// Splits `text` at every `sep`.
std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(sep, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

/// Parses click:X:Y, drag:DX:DY, pan:DX:DY and wheel:N. @return an error message or "".
std::string parse_pointer(std::string_view item, InputEvent& event) {
  const std::vector<std::string_view> f = split(item, ':');
  const bool wheel = f[0] == "wheel";
  if (f.size() != (wheel ? 2u : 3u))
    return wheel ? "expected wheel:N" : fmt::format("expected {}:X:Y", f[0]);
  std::array<int, 2> v{};
  for (std::size_t i = 1; i < f.size(); ++i) {
    const auto n = parse_int(f[i]);
    if (!n) return fmt::format("'{}' is not a whole number", f[i]);
    v[i - 1] = *n;
  }
  event.type = wheel             ? InputEvent::Type::wheel
               : f[0] == "click" ? InputEvent::Type::click
                                 : InputEvent::Type::drag;
  event.right_button = f[0] == "pan";
  event.x = v[0];
  event.y = v[1];
  if (event.type == InputEvent::Type::click && (v[0] < 0 || v[1] < 0))
    return "a click needs a pixel inside the window (X, Y >= 0)";
  return "";
}

/// Parses [ctrl+][shift+]KEY. @return an error message or "".
std::string parse_key(std::string_view item, InputEvent& event) {
  for (bool more = true; more;) {
    more = false;
    if (item.starts_with("ctrl+") && item.size() > 5) {
      event.ctrl = more = true;
      item.remove_prefix(5);
    } else if (item.starts_with("shift+") && item.size() > 6) {
      event.shift = more = true;
      item.remove_prefix(6);
    }
  }
  if (!is_key_name(item)) return fmt::format("'{}' is not a key name", item);
  event.key = std::string(item);
  return "";
}

/// Parses wait:change. @return an error message or "".
std::string parse_wait(std::string_view item, InputEvent& event) {
  if (item != "wait:change") return "expected wait:change";
  event.type = InputEvent::Type::wait_change;
  return "";
}

}  // namespace

bool is_key_name(std::string_view name) {
  if (name.size() == 1)
    return (name[0] >= 'a' && name[0] <= 'z') || (name[0] >= '0' && name[0] <= '9');
  return std::find(kNamedKeys.begin(), kNamedKeys.end(), name) != kNamedKeys.end();
}

Result<std::vector<InputEvent>> parse_key_script(std::string_view script) {
  std::vector<InputEvent> events;
  if (script.empty()) return events;
  std::size_t index = 0;
  for (std::string_view item : split(script, ',')) {
    ++index;
    InputEvent event;
    const bool pointer = item.starts_with("click:") || item.starts_with("drag:") ||
                         item.starts_with("pan:") || item.starts_with("wheel:");
    const std::string problem = item.starts_with("wait:") ? parse_wait(item, event)
                                : pointer                 ? parse_pointer(item, event)
                                                          : parse_key(item, event);
    if (!problem.empty())
      return Result<std::vector<InputEvent>>::failure(
          Code::usage_error, fmt::format("--keys: input {} '{}': {}", index, item, problem));
    events.push_back(std::move(event));
  }
  return events;
}

}  // namespace roomcad
