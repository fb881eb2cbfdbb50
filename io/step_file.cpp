// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/step_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace roomcad::step {

void append_real(std::string& out, double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x + 0.0).ptr;  // -0 -> 0
  const std::string_view digits(buffer, static_cast<std::size_t>(end - buffer));
  const std::size_t e = digits.find('e');
  const std::string_view mantissa = digits.substr(0, e);
  out += mantissa;
  if (mantissa.find('.') == std::string_view::npos) out += '.';
  if (e != std::string_view::npos) {
    out += 'E';
    out += digits.substr(e + 1);
  }
}

namespace {

/// @return the code point starting at text[i] (advancing i), or U+FFFD for a malformed byte.
std::uint32_t next_code_point(std::string_view text, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  const std::size_t extra = b0 >= 0xf0 ? 3 : b0 >= 0xe0 ? 2 : b0 >= 0xc0 ? 1 : 0;
  if ((b0 >= 0x80 && extra == 0) || i + extra >= text.size()) {
    ++i;
    return 0xfffd;
  }
  std::uint32_t cp = extra == 0 ? b0 : b0 & (0x3f >> extra);
  for (std::size_t k = 1; k <= extra; ++k) cp = (cp << 6) | (byte(i + k) & 0x3f);
  i += extra + 1;
  return cp;
}

}  // namespace

void append_string(std::string& out, std::string_view text) {
  out += '\'';
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c >= 0x20 && c < 0x7f) {
      out += c;
      if (c == '\'' || c == '\\') out += c;
      ++i;
      continue;
    }
    const std::uint32_t cp = next_code_point(text, i);
    out += "\\X2\\";
    if (cp >= 0x10000) {  // a surrogate pair
      const std::uint32_t v = cp - 0x10000;
      out += fmt::format("{:04X}{:04X}", 0xd800 + (v >> 10), 0xdc00 + (v & 0x3ff));
    } else {
      out += fmt::format("{:04X}", cp);
    }
    out += "\\X0\\";
  }
  out += '\'';
}

int Writer::add(std::string_view type, std::string_view parameters) {
  const int n = next_++;
  data_ += '#';
  data_ += std::to_string(n);
  data_ += '=';
  data_ += type;
  data_ += '(';
  data_ += parameters;
  data_ += ");\n";
  return n;
}

std::string Writer::finish(std::string_view file_name, std::string_view schema,
                           std::string_view description) const {
  std::string out = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((";
  append_string(out, description);
  out += "),'2;1');\nFILE_NAME(";
  append_string(out, file_name);
  // A fixed time stamp: the same plan gives the same bytes (docs: deterministic output).
  out += ",'1970-01-01T00:00:00',(''),(''),'roomcad','roomcad','');\nFILE_SCHEMA((";
  append_string(out, schema);
  out += "));\nENDSEC;\nDATA;\n";
  out += data_;
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

std::string ref(int n) { return '#' + std::to_string(n); }

const Instance* File::find(std::uint32_t id) const {
  const auto it = index.find(id);
  return it == index.end() ? nullptr : &instances[it->second];
}

}  // namespace roomcad::step
