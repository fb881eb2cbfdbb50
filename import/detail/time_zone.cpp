// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/time_zone.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace roomcad::sh3d {
namespace {

constexpr std::size_t kHeaderBytes = 44;

std::int64_t big_endian(const std::string& bytes, std::size_t at, std::size_t size) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < size; ++i)
    value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
  if (size == 4) return static_cast<std::int32_t>(static_cast<std::uint32_t>(value));
  return static_cast<std::int64_t>(value);
}

/// The counts of a TZif header at `at` (RFC 8536): isutcnt, isstdcnt, leapcnt, timecnt,
/// typecnt, charcnt.
struct Counts {
  std::size_t isut = 0, isstd = 0, leap = 0, time = 0, type = 0, chars = 0;
  [[nodiscard]] std::size_t data_bytes(std::size_t time_size) const {
    return time * time_size + time + type * 6 + chars + leap * (time_size + 4) + isstd + isut;
  }
};

std::optional<Counts> read_header(const std::string& bytes, std::size_t at) {
  if (bytes.size() < at + kHeaderBytes || bytes.compare(at, 4, "TZif") != 0) return std::nullopt;
  std::size_t c[6];
  for (std::size_t i = 0; i < 6; ++i)
    c[i] = static_cast<std::size_t>(big_endian(bytes, at + 20 + 4 * i, 4));
  return Counts{c[0], c[1], c[2], c[3], c[4], c[5]};
}

bool safe_zone_name(std::string_view name) {
  if (name.empty() || name.front() == '/' || name.find("..") != std::string_view::npos)
    return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '_' || c == '-' ||
           c == '+';
  });
}

}  // namespace

std::optional<double> zone_utc_offset(std::string_view name, std::int64_t unix_seconds) {
  if (!safe_zone_name(name)) return std::nullopt;
  std::ifstream in("/usr/share/zoneinfo/" + std::string(name), std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::optional<Counts> counts = read_header(bytes, 0);
  if (!counts) return std::nullopt;
  std::size_t at = kHeaderBytes, time_size = 4;
  if (bytes[4] >= '2') {  // the 64-bit block follows the 32-bit one: read it
    at += counts->data_bytes(4);
    counts = read_header(bytes, at);
    if (!counts) return std::nullopt;
    at += kHeaderBytes, time_size = 8;
  }
  if (counts->type == 0 || bytes.size() < at + counts->data_bytes(time_size)) return std::nullopt;
  const std::size_t indices = at + counts->time * time_size;
  const std::size_t types = indices + counts->time;
  std::size_t type = 0;  // before the first transition: the first type
  for (std::size_t i = 0; i < counts->time; ++i) {
    if (big_endian(bytes, at + i * time_size, time_size) > unix_seconds) break;
    type = static_cast<unsigned char>(bytes[indices + i]);
  }
  if (type >= counts->type) return std::nullopt;
  return static_cast<double>(big_endian(bytes, types + 6 * type, 4)) / 3600.0;
}

}  // namespace roomcad::sh3d
