// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/utf8_text.h"

#include <fmt/format.h>

namespace roomcad {
namespace {

/// @return the length of the well-formed UTF-8 sequence that starts at `text[at]`, or 0 when
/// none does (RFC 3629's table of well-formed byte sequences).
std::size_t well_formed_length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80;   // the range of the second byte, which rules out overlong
  unsigned char high = 0xbf;  // forms, surrogates and code points above U+10FFFF
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    if (lead == 0xe0) low = 0xa0;
    if (lead == 0xed) high = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    if (lead == 0xf0) low = 0x90;
    if (lead == 0xf4) high = 0x8f;
  } else {
    return 0;
  }
  if (at + length > text.size() || byte(at + 1) < low || byte(at + 1) > high) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if ((byte(at + i) & 0xc0) != 0x80) return 0;
  return length;
}

/// @return `text` with each byte that starts no well-formed sequence given to
/// `replace(byte, out)`, which appends what stands for it; the rest copied as it is.
template <class Replace>
std::string with_ill_formed_bytes_replaced(std::string_view text, Replace&& replace) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = well_formed_length(text, at);
    if (length > 0) {
      out.append(text.substr(at, length));
      at += length;
    } else {
      replace(static_cast<unsigned char>(text[at++]), out);
    }
  }
  return out;
}

}  // namespace

std::optional<std::size_t> first_ill_formed_utf8(std::string_view text) {
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = well_formed_length(text, at);
    if (length == 0) return at;
    at += length;
  }
  return std::nullopt;
}

std::string utf8_from_latin1_where_ill_formed(std::string_view text) {
  return with_ill_formed_bytes_replaced(text, [](unsigned char byte, std::string& out) {
    out += static_cast<char>(0xc0 | (byte >> 6));  // >= 0x80: two bytes in UTF-8
    out += static_cast<char>(0x80 | (byte & 0x3f));
  });
}

std::string printable_utf8(std::string_view text) {
  return with_ill_formed_bytes_replaced(
      text, [](unsigned char byte, std::string& out) { out += fmt::format("\\x{:02X}", byte); });
}

}  // namespace roomcad
