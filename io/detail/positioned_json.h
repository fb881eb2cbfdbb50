// SPDX-License-Identifier: GPL-3.0-or-later
// JSON parsing that remembers where every key and value starts in the text, so that the plan
// reader can point at the exact line and column of a wrong value (nlohmann's DOM has no positions).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include <nlohmann/json.hpp>

namespace roomcad::io_detail {

/// Objects keep their keys in file order, so that diagnostics come in file order.
using Json = nlohmann::ordered_json;

/// Deepest nesting of arrays and objects accepted (deeper input is a syntax error, not a crash).
inline constexpr std::size_t kMaxJsonDepth = 256;

/// Why a text is not a JSON document we accept.
struct JsonSyntaxError {
  std::size_t offset = 0;   ///< byte offset in the text where the problem was seen
  std::string pointer;      ///< JSON pointer of the value concerned, when known
  std::string message;      ///< what is wrong, without the position
  bool not_finite = false;  ///< a number too large for a double (invalid_value, not parse_error)
};

struct PositionedJson {
  Json root;
  /// Byte offset of the first character of each value, by JSON pointer ("" is the root).
  std::unordered_map<std::string, std::size_t> value_offsets;
  /// Byte offset of the opening quote of each object key, by the JSON pointer of its value.
  std::unordered_map<std::string, std::size_t> key_offsets;
  std::optional<JsonSyntaxError>
      error;  ///< set when the text is not accepted; root is then partial
};

/// Parses `text` (strict JSON, UTF-8; duplicate keys and nesting deeper than kMaxJsonDepth are
/// errors). Never throws on any input. O(n) in the text length.
/// @param[in] depth  how many arrays and objects enclose `text` in its document (for a value
///                   cut out of one): they count towards kMaxJsonDepth.
[[nodiscard]] PositionedJson parse_positioned_json(std::string_view text, std::size_t depth = 0);

/// A 1-based line and column (columns count characters, not bytes).
struct LineColumn {
  std::size_t line = 1;
  std::size_t column = 1;
};

/// @return the line and column of byte `offset` of `text` (clamped to the text's end). O(offset).
[[nodiscard]] LineColumn line_column_at(std::string_view text, std::size_t offset);

/// Line and column of many offsets of one text, scanning on from the previous answer: O(n) in
/// all for offsets in increasing order (a reader reporting in file order), where calling
/// line_column_at for each of k problems would be O(n k), a hang for a big file full of them.
class LineColumnCursor {
 public:
  explicit LineColumnCursor(std::string_view text) : text_(text) {}
  /// @return line_column_at(text, offset). O(distance from the previous offset) going forward,
  ///   O(offset) going back.
  [[nodiscard]] LineColumn at(std::size_t offset);

 private:
  std::string_view text_;
  std::size_t offset_ = 0;  ///< where `at_` is
  LineColumn at_;
};

/// @return `parent` extended by one reference token, escaped as RFC 6901 requires (~0, ~1).
[[nodiscard]] std::string pointer_child(const std::string& parent, std::string_view token);
/// @return `parent` extended by an array index.
[[nodiscard]] std::string pointer_child(const std::string& parent, std::size_t index);

}  // namespace roomcad::io_detail
