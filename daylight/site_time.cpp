// SPDX-License-Identifier: GPL-3.0-or-later
#include "daylight/site_time.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace roomcad {
namespace {

/// Reads exactly `digits` decimal digits at `text[at]`. @return the number, or -1.
int read_digits(std::string_view text, std::size_t at, std::size_t digits) {
  if (at + digits > text.size()) return -1;
  int value = 0;
  const auto [end, error] = std::from_chars(text.data() + at, text.data() + at + digits, value);
  return error == std::errc{} && end == text.data() + at + digits ? value : -1;
}

bool valid_date(std::int64_t year, int month, int day) {
  static constexpr int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12 || day < 1 || day > kDays[month - 1]) return false;
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month != 2 || day <= 28 || leap;
}

/// Reads `YYYY-MM-DD` at the start of `text`. @return the day, or nothing.
std::optional<CivilDay> read_date(std::string_view text) {
  const int year = read_digits(text, 0, 4), month = read_digits(text, 5, 2),
            day = read_digits(text, 8, 2);
  if (year < 0 || month < 0 || day < 0 || text[4] != '-' || text[7] != '-') return std::nullopt;
  if (!valid_date(year, month, day)) return std::nullopt;
  return civil_day(year, month, day);
}

/// Reads a UTC offset (`Z`, `+03:00`, `+0300`, `-05`). @return its hours, or nothing.
std::optional<double> read_offset(std::string_view text) {
  if (text == "Z") return 0.0;
  if (text.size() < 3 || (text[0] != '+' && text[0] != '-')) return std::nullopt;
  const int hours = read_digits(text, 1, 2);
  int minutes = 0;
  if (text.size() == 6 && text[3] == ':') minutes = read_digits(text, 4, 2);
  else if (text.size() == 5) minutes = read_digits(text, 3, 2);
  else if (text.size() != 3) return std::nullopt;
  if (hours < 0 || hours > 14 || minutes < 0 || minutes > 59) return std::nullopt;
  return (text[0] == '-' ? -1.0 : 1.0) * (hours + minutes / 60.0);
}

}  // namespace

CivilDay civil_day(std::int64_t year, int month, int day) {
  // Howard Hinnant's days_from_civil: exact for every proleptic Gregorian date.
  year -= month <= 2;
  const std::int64_t era = (year >= 0 ? year : year - 399) / 400;
  const std::int64_t yoe = year - era * 400;
  const std::int64_t doy = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

std::string format_site_date(CivilDay z) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t doe = z - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  const std::int64_t day = doy - (153 * mp + 2) / 5 + 1;
  const std::int64_t month = mp < 10 ? mp + 3 : mp - 9;
  const std::int64_t year = yoe + era * 400 + (month <= 2);
  return fmt::format("{:04}-{:02}-{:02}", year, month, day);
}

Result<CivilDay> parse_site_date(std::string_view text) {
  if (text.size() == 10)
    if (const auto day = read_date(text)) return *day;
  return Result<CivilDay>::failure(
      Code::usage_error,
      fmt::format("'{}' is not a date; expected YYYY-MM-DD, e.g. 2026-04-22", text));
}

Result<UtcSeconds> parse_site_time(std::string_view text, double utc_offset_hours) {
  const auto refuse = [&] {
    return Result<UtcSeconds>::failure(
        Code::usage_error,
        fmt::format("'{}' is not a time; expected YYYY-MM-DDTHH:MM[:SS][Z|+HH:MM], e.g. "
                    "2026-04-22T14:30 (local time at the site unless an offset is given)",
                    text));
  };
  if (text.size() < 16 || (text[10] != 'T' && text[10] != ' ')) return refuse();
  const auto day = read_date(text.substr(0, 10));
  const int hour = read_digits(text, 11, 2), minute = read_digits(text, 14, 2);
  if (!day || hour < 0 || hour > 23 || minute < 0 || minute > 59 || text[13] != ':')
    return refuse();
  std::size_t at = 16;
  int second = 0;
  if (text.size() >= 19 && text[16] == ':') {
    second = read_digits(text, 17, 2);
    if (second < 0 || second > 59) return refuse();
    at = 19;
  }
  double offset = utc_offset_hours;
  if (at < text.size()) {
    const auto own = read_offset(text.substr(at));
    if (!own) return refuse();
    offset = *own;
  }
  return local_midnight(*day, offset) + hour * 3600.0 + minute * 60.0 + second;
}

CivilDay local_day(UtcSeconds t, double utc_offset_hours) {
  return static_cast<CivilDay>(std::floor((t + utc_offset_hours * 3600.0) / kSecondsPerDay));
}

UtcSeconds local_midnight(CivilDay day, double utc_offset_hours) {
  return static_cast<double>(day) * kSecondsPerDay - utc_offset_hours * 3600.0;
}

std::string format_clock(UtcSeconds t, double utc_offset_hours, std::optional<CivilDay> day) {
  const double local = std::round(t + utc_offset_hours * 3600.0);
  if (day && local == static_cast<double>(*day + 1) * kSecondsPerDay) return "24:00:00";
  const auto seconds =
      static_cast<std::int64_t>(local - std::floor(local / kSecondsPerDay) * kSecondsPerDay);
  return fmt::format("{:02}:{:02}:{:02}", seconds / 3600, seconds / 60 % 60, seconds % 60);
}

}  // namespace roomcad
