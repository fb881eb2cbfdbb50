// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/detail/json_value_text.h"

#include <cstddef>

#include "io/detail/json_text.h"

namespace roomcad::io_detail {
namespace {

using JsonType = simdjson::ondemand::json_type;

std::string count_text(std::size_t n) {
  return n == 0 ? "an empty array"
                : "an array of " + std::to_string(n) + (n == 1 ? " item" : " items");
}

}  // namespace

/// A string as a message shows it: quoted, escaped, cut after 40 bytes (whole characters).
std::string quote_for_message(std::string_view text) {
  std::string s;
  append_string(s, text);
  if (s.size() > 42) {
    std::size_t cut = 40;
    while (cut > 1 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
    s = s.substr(0, cut) + "...\"";
  }
  return s;
}

/// "an object", "an array of 3 items", "\"abc\"", "12.5": how a found value is shown.
std::string describe(simdjson::ondemand::value& v) {
  switch (v.type().value()) {
    case JsonType::object: return "an object";
    case JsonType::array: {
      std::size_t n = 0;
      for (auto item : v.get_array()) ++n, (void)item;
      return count_text(n);
    }
    case JsonType::string: return quote_for_message(v.get_string().value());
    default: break;
  }
  const PositionedJson scalar = parse_positioned_json(v.raw_json_token());
  if (scalar.error) throw Malformed{};
  return canonical_text(scalar.root);
}

/// describe, for a whole document read by the positioned parser.
std::string describe_json(const Json& v) {
  if (v.is_object()) return "an object";
  if (v.is_array()) return count_text(v.size());
  return v.is_string() ? quote_for_message(v.get_ref<const std::string&>()) : canonical_text(v);
}

/// @return the whole text of a value (consuming it).
std::string_view raw_json(simdjson::ondemand::value& v) {
  switch (v.type().value()) {
    case JsonType::object: return v.get_object().value().raw_json().value();
    case JsonType::array: return v.get_array().value().raw_json().value();
    default: break;
  }
  std::string_view token = v.raw_json_token();  // a scalar, with the spaces after it
  while (!token.empty() && (token.back() == ' ' || token.back() == '\t' || token.back() == '\n' ||
                            token.back() == '\r'))
    token.remove_suffix(1);
  return token;
}

}  // namespace roomcad::io_detail
