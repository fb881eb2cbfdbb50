// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/detail/positioned_json.h"

#include <algorithm>

#include <iterator>
#include <vector>

namespace roomcad::io_detail {
namespace {

/// A char iterator that tells how far nlohmann's lexer has read: every increment advances a
/// shared counter, so at each SAX event the counter is just past the token that caused it (one
/// further after a number, whose end the lexer finds by reading one character too many).
class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* at, std::size_t* consumed) : at_(at), consumed_(consumed) {}
  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    ++at_;
    ++*consumed_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  friend bool operator==(const CountingIterator& a, const CountingIterator& b) {
    return a.at_ == b.at_;
  }

 private:
  const char* at_;
  std::size_t* consumed_;
};

bool is_separator(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ':' || c == ',';
}

/// Builds an ordered_json DOM from SAX events, recording where each key and value starts.
class PositionedBuilder {
 public:
  PositionedBuilder(std::string_view text, const std::size_t* consumed, std::size_t depth,
                    PositionedJson* out)
      : text_(text), consumed_(consumed), depth_(depth), out_(out) {}

  bool null() { return add_value(Json(nullptr)); }
  bool boolean(bool b) { return add_value(Json(b)); }
  bool number_integer(Json::number_integer_t n) {
    // JSON's "-0" is the double -0, which nlohmann reads as the integer 0: keep its sign.
    if (n == 0 && text_[first_non_separator()] == '-') return add_value(Json(-0.0));
    return add_value(Json(n));
  }
  bool number_unsigned(Json::number_unsigned_t n) { return add_value(Json(n)); }
  bool number_float(Json::number_float_t x, const std::string&) { return add_value(Json(x)); }
  bool string(std::string& s) { return add_value(Json(std::move(s))); }
  bool binary(Json::binary_t&) { return fail(token_start(), "binary values are not JSON"); }

  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(std::string& k) {
    const std::size_t at = token_start();
    Frame& top = stack_.back();
    if (top.value->contains(k)) {
      return fail(at, "duplicate key \"" + k + "\" in one object", pointer_child(top.pointer, k));
    }
    top.key = std::move(k);
    out_->key_offsets[pointer_child(top.pointer, top.key)] = at;
    return true;
  }

  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& ex) {
    if (ex.id == 406) {  // number overflow: an out_of_range reported through this callback
      const std::size_t at = token_start();
      const std::string number(text_.substr(at, *consumed_ - at));
      JsonSyntaxError e{at, next_pointer(), "", true};
      e.message = "number " + trimmed(number) + " is too large for a double";
      out_->error = std::move(e);
      return false;
    }
    std::string message = ex.what();
    // "[json.exception.parse_error.101] parse error at line 1, column 6: syntax error ..."
    if (const auto colon = message.find(": ");
        colon != std::string::npos && message.compare(0, 1, "[") == 0) {
      message = message.substr(colon + 2);
    }
    out_->error = JsonSyntaxError{position > 0 ? position - 1 : 0, "", std::move(message), false};
    return false;
  }

 private:
  struct Frame {
    Json* value;
    std::string pointer;
    std::string key;  ///< the pending key, for objects
  };

  static std::string trimmed(std::string s) {
    while (!s.empty() && (is_separator(s.back()) || s.back() == ']' || s.back() == '}'))
      s.pop_back();
    return s;
  }

  /// The first byte of the token just read: past the previous event's end, skipping
  /// whitespace and separators.
  std::size_t token_start() {
    const std::size_t at = first_non_separator();
    previous_end_ = *consumed_;
    return at;
  }

  std::size_t first_non_separator() const {
    std::size_t at = previous_end_;
    if (at == 0 && text_.substr(0, 3) == "\xEF\xBB\xBF") at = 3;  // nlohmann skips a UTF-8 BOM
    while (at < text_.size() && is_separator(text_[at])) ++at;
    return at;
  }

  std::string next_pointer() const {
    if (stack_.empty()) return "";
    const Frame& top = stack_.back();
    return top.value->is_array() ? pointer_child(top.pointer, top.value->size())
                                 : pointer_child(top.pointer, top.key);
  }

  /// Places a value in its parent; returns where it went and its pointer.
  std::pair<Json*, std::string> place(Json value) {
    const std::size_t at = token_start();
    std::string pointer = next_pointer();
    out_->value_offsets[pointer] = at;
    if (stack_.empty()) {
      out_->root = std::move(value);
      return {&out_->root, pointer};
    }
    Json& parent = *stack_.back().value;
    if (parent.is_array()) {
      parent.push_back(std::move(value));
      return {&parent.back(), pointer};
    }
    Json& slot = parent[stack_.back().key];
    slot = std::move(value);
    return {&slot, pointer};
  }

  bool add_value(Json value) {
    place(std::move(value));
    return true;
  }

  bool open(Json container) {
    if (depth_ + stack_.size() >= kMaxJsonDepth) {
      return fail(token_start(),
                  "nesting deeper than " + std::to_string(kMaxJsonDepth) + " arrays and objects",
                  next_pointer());
    }
    auto [where, pointer] = place(std::move(container));
    stack_.push_back(Frame{where, std::move(pointer), {}});
    return true;
  }

  bool close() {
    previous_end_ = *consumed_;
    stack_.pop_back();
    return true;
  }

  bool fail(std::size_t at, std::string message, std::string pointer = "") {
    out_->error = JsonSyntaxError{at, std::move(pointer), std::move(message), false};
    return false;
  }

  std::string_view text_;
  const std::size_t* consumed_;
  std::size_t depth_;  ///< containers enclosing the text
  PositionedJson* out_;
  std::vector<Frame> stack_;
  std::size_t previous_end_ = 0;
};

}  // namespace

PositionedJson parse_positioned_json(std::string_view text, std::size_t depth) {
  PositionedJson out;
  std::size_t consumed = 0;
  PositionedBuilder builder(text, &consumed, depth, &out);
  try {
    const bool ok =
        Json::sax_parse(CountingIterator(text.data(), &consumed),
                        CountingIterator(text.data() + text.size(), &consumed), &builder);
    if (!ok && !out.error) out.error = JsonSyntaxError{consumed, "", "not a JSON document", false};
  } catch (const std::exception& e) {  // allocation failure and the like: still no crash
    out.error = JsonSyntaxError{consumed, "", e.what(), false};
  }
  return out;
}

namespace {

/// Advances `at` over bytes [from, to) of `text`.
void advance(std::string_view text, std::size_t from, std::size_t to, LineColumn& at) {
  for (std::size_t i = from; i < to; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++at.line;
      at.column = 1;
    } else if ((c & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
      ++at.column;
    }
  }
}

}  // namespace

LineColumn line_column_at(std::string_view text, std::size_t offset) {
  LineColumn at;
  advance(text, 0, std::min(offset, text.size()), at);
  return at;
}

LineColumn LineColumnCursor::at(std::size_t offset) {
  offset = std::min(offset, text_.size());
  if (offset < offset_) {
    offset_ = 0;
    at_ = LineColumn{};
  }
  advance(text_, offset_, offset, at_);
  offset_ = offset;
  return at_;
}

std::string pointer_child(const std::string& parent, std::string_view token) {
  std::string out = parent;
  out += '/';
  for (char c : token) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string pointer_child(const std::string& parent, std::size_t index) {
  return parent + '/' + std::to_string(index);
}

}  // namespace roomcad::io_detail
