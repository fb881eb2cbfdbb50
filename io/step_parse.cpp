// SPDX-License-Identifier: GPL-3.0-or-later
// The STEP physical file reader (io/step_file.h): one pass over the text, no copies of it.
#include <algorithm>
#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "io/step_file.h"
#include "io/utf8_text.h"

namespace roomcad::step {
namespace {

constexpr int kMaxDepth = 64;

/// Thrown inside the parser only; parse() turns it into a parse_error with the line.
struct ParseFailure {
  std::size_t at;
  std::string what;
};

/// Appends code point `cp` in UTF-8; a surrogate (half of a UTF-16 pair left unpaired) or a
/// value past U+10FFFF, which UTF-8 cannot hold, as U+FFFD.
void append_utf8(std::string& out, std::uint32_t cp) {
  if ((cp >= 0xd800 && cp < 0xe000) || cp > 0x10ffff) cp = 0xfffd;
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xc0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xe0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else {
    out += static_cast<char>(0xf0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  }
}

std::uint32_t hex_value(std::string_view digits) {
  std::uint32_t v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, 16);
  return ec == std::errc{} && end == digits.data() + digits.size() ? v : 0xfffd;
}

/// Decodes the escapes of a STEP string's content (quotes already undoubled): \X2\..\X0\ as
/// UTF-16, \X\hh as ISO 8859-1, a doubled backslash; other escapes (\S\, \P\) stay as written.
/// STEP allows only ASCII between the quotes, yet exporters write names in raw UTF-8 or
/// Latin-1: raw bytes that are no UTF-8 are read as Latin-1, so the text is always UTF-8.
std::string decode_string(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size();) {
    if (raw.compare(i, 4, "\\X2\\") == 0) {
      const std::size_t end = raw.find("\\X0\\", i + 4);
      const std::string_view hex =
          raw.substr(i + 4, end == std::string_view::npos ? 0 : end - i - 4);
      for (std::size_t k = 0; k + 4 <= hex.size(); k += 4) {
        std::uint32_t cp = hex_value(hex.substr(k, 4));
        const std::uint32_t next = k + 8 <= hex.size() ? hex_value(hex.substr(k + 4, 4)) : 0;
        if (cp >= 0xd800 && cp < 0xdc00 && next >= 0xdc00 && next < 0xe000) {  // a pair
          cp = 0x10000 + ((cp - 0xd800) << 10) + (next - 0xdc00);
          k += 4;
        }
        append_utf8(out, cp);
      }
      i = end == std::string_view::npos ? raw.size() : end + 4;
    } else if (raw.compare(i, 3, "\\X\\") == 0 && i + 5 <= raw.size()) {
      append_utf8(out, hex_value(raw.substr(i + 3, 2)));
      i += 5;
    } else if (raw.compare(i, 2, "\\\\") == 0) {
      out += '\\';
      i += 2;
    } else {
      out += raw[i++];
    }
  }
  return first_ill_formed_utf8(out) ? utf8_from_latin1_where_ill_formed(out) : out;
}

class Parser {
 public:
  explicit Parser(std::string_view text) : s_(text) {}

  File run() {
    skip();
    expect_word("ISO-10303-21");
    expect(';');
    read_header();
    while (true) {
      skip();
      if (try_word("ENDSEC")) break;
      read_instance();
    }
    return std::move(file_);
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
  File file_;

  [[noreturn]] void fail(std::string what) const { throw ParseFailure{i_, std::move(what)}; }

  void skip() {
    while (i_ < s_.size()) {
      if (std::isspace(static_cast<unsigned char>(s_[i_]))) {
        ++i_;
      } else if (s_.compare(i_, 2, "/*") == 0) {
        const std::size_t end = s_.find("*/", i_ + 2);
        if (end == std::string_view::npos) fail("an unterminated comment");
        i_ = end + 2;
      } else {
        return;
      }
    }
  }
  char peek() {
    skip();
    return i_ < s_.size() ? s_[i_] : '\0';
  }
  void expect(char c) {
    if (peek() != c) fail(fmt::format("expected '{}'", c));
    ++i_;
  }
  std::string_view word() {
    skip();
    const std::size_t start = i_;
    while (i_ < s_.size() &&
           (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == '-'))
      ++i_;
    return s_.substr(start, i_ - start);
  }
  bool try_word(std::string_view w) {
    skip();
    if (s_.compare(i_, w.size(), w) != 0) return false;
    i_ += w.size();
    return true;
  }
  void expect_word(std::string_view w) {
    if (!try_word(w)) fail(fmt::format("expected {}", w));
  }

  /// HEADER; ... ENDSEC; DATA; keeping the first schema name of FILE_SCHEMA.
  void read_header() {
    expect_word("HEADER");
    expect(';');
    while (!try_word("ENDSEC")) {
      const std::string_view name = word();
      if (name.empty()) fail("expected a header entity or ENDSEC");
      expect('(');
      std::vector<Value> parameters;
      read_list_items(parameters, 1);
      expect(';');
      if (name == "FILE_SCHEMA" && !parameters.empty() && !parameters[0].items.empty()) {
        file_.schema = parameters[0].items[0].text;
        std::transform(file_.schema.begin(), file_.schema.end(), file_.schema.begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
      }
    }
    expect(';');
    expect_word("DATA");
    expect(';');
  }

  void read_instance() {
    expect('#');
    std::uint32_t id = 0;
    const auto [end, ec] = std::from_chars(s_.data() + i_, s_.data() + s_.size(), id);
    if (ec != std::errc{}) fail("expected an instance number after '#'");
    i_ = static_cast<std::size_t>(end - s_.data());
    expect('=');
    Instance instance{.id = id};
    if (peek() == '(') {  // a complex instance: (A(..) B(..))
      ++i_;
      while (peek() != ')') {
        const std::string_view part = word();
        if (part.empty()) fail("expected an entity name in a complex instance");
        if (instance.type.empty()) instance.type = std::string(part);
        expect('(');
        read_list_items(instance.parameters, 1);
      }
      ++i_;
    } else {
      instance.type = std::string(word());
      if (instance.type.empty()) fail("expected an entity name");
      expect('(');
      read_list_items(instance.parameters, 1);
    }
    expect(';');
    if (file_.instances.size() >= kMaxInstances) throw ParseFailure{i_, "too many instances"};
    if (!file_.index.emplace(id, file_.instances.size()).second)
      fail(fmt::format("instance #{} is defined twice", id));
    file_.instances.push_back(std::move(instance));
  }

  /// Reads values up to and including the closing ')' of a list whose '(' was read.
  void read_list_items(std::vector<Value>& items, int depth) {
    if (depth > kMaxDepth) fail(fmt::format("lists nested deeper than {}", kMaxDepth));
    if (peek() == ')') {
      ++i_;
      return;
    }
    while (true) {
      items.push_back(read_value(depth));
      const char c = peek();
      ++i_;
      if (c == ')') return;
      if (c != ',') fail("expected ',' or ')' in a list");
    }
  }

  Value read_value(int depth) {
    const char c = peek();
    Value v;
    if (c == '$' || c == '*') {
      ++i_;
      v.kind = c == '$' ? Value::Kind::null : Value::Kind::derived;
    } else if (c == '#') {
      ++i_;
      const auto [end, ec] = std::from_chars(s_.data() + i_, s_.data() + s_.size(), v.id);
      if (ec != std::errc{}) fail("expected an instance number after '#'");
      i_ = static_cast<std::size_t>(end - s_.data());
      v.kind = Value::Kind::ref;
    } else if (c == '\'' || c == '"') {
      read_string(v, c);
    } else if (c == '.') {
      const std::size_t end = s_.find('.', i_ + 1);
      if (end == std::string_view::npos) fail("an unterminated enumeration");
      v.kind = Value::Kind::enumeration;
      v.text = std::string(s_.substr(i_ + 1, end - i_ - 1));
      i_ = end + 1;
    } else if (c == '(') {
      ++i_;
      v.kind = Value::Kind::list;
      read_list_items(v.items, depth + 1);
    } else if (c == '-' || c == '+' || std::isdigit(static_cast<unsigned char>(c))) {
      read_number(v);
    } else if (std::isalpha(static_cast<unsigned char>(c))) {
      v.kind = Value::Kind::typed;
      v.text = std::string(word());
      expect('(');
      read_list_items(v.items, depth + 1);
    } else {
      fail(c == '\0' ? "unexpected end of file" : fmt::format("unexpected '{}'", c));
    }
    return v;
  }

  void read_string(Value& v, char quote) {
    std::string raw;
    for (++i_;; ++i_) {
      if (i_ >= s_.size()) fail("an unterminated string");
      if (s_[i_] != quote) {
        raw += s_[i_];
      } else if (i_ + 1 < s_.size() && s_[i_ + 1] == quote) {
        raw += quote;
        ++i_;
      } else {
        break;
      }
    }
    ++i_;
    v.kind = Value::Kind::string;
    v.text = decode_string(raw);
  }

  void read_number(Value& v) {
    std::size_t end = i_ + 1;
    bool real = false;
    while (end < s_.size() &&
           (std::isdigit(static_cast<unsigned char>(s_[end])) || s_[end] == '.' || s_[end] == 'E' ||
            s_[end] == 'e' ||
            ((s_[end] == '-' || s_[end] == '+') && (s_[end - 1] == 'E' || s_[end - 1] == 'e')))) {
      real = real || !std::isdigit(static_cast<unsigned char>(s_[end]));
      ++end;
    }
    // from_chars reads "1." and "1.E-5" as strtod does, but not a leading '+'.
    const std::size_t start = i_ + (s_[i_] == '+');
    const auto [stop, ec] = std::from_chars(s_.data() + start, s_.data() + end, v.number);
    if (ec != std::errc{} || stop != s_.data() + end)
      fail(fmt::format("\"{}\" is not a number", s_.substr(i_, end - i_)));
    v.kind = real ? Value::Kind::real : Value::Kind::integer;
    i_ = end;
  }
};

}  // namespace

Result<File> parse(std::string_view text, std::string_view name) {
  try {
    return Parser(text).run();
  } catch (const ParseFailure& failure) {
    const std::size_t at = std::min(failure.at, text.size());
    const std::size_t line =
        1 + static_cast<std::size_t>(
                std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    const Code code = failure.what == "too many instances" ? Code::too_large : Code::parse_error;
    return Result<File>::failure(
        code,
        fmt::format("{}: line {}: {} (a STEP physical file, ISO 10303-21, is expected)", name, line,
                    failure.what),
        Location{.file = std::string(name), .pointer = "", .line = line, .column = 0});
  }
}

}  // namespace roomcad::step
