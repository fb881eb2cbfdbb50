// SPDX-License-Identifier: GPL-3.0-or-later
// Times at a site: ISO 8601 local times and dates read and written in a site's UTC offset
// (docs/plan-format.md, "Sun and sunlight"). A time is seconds since 1970-01-01T00:00 UTC.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace roomcad {

/// Seconds since 1970-01-01T00:00:00 UTC (negative before), as UTC counts them (no leap
/// seconds): what the sun's position is computed for.
using UtcSeconds = double;

/// A calendar day: days since 1970-01-01 (proleptic Gregorian).
using CivilDay = std::int64_t;

inline constexpr double kSecondsPerDay = 86400.0;

/// Reads `2026-04-22T14:30`, `2026-04-22T14:30:05`, with an optional offset (`Z`, `+03:00`,
/// `-0530`): local time at `utc_offset_hours` unless the text carries its own offset.
/// @return the time, or a usage_error naming the text and the form expected. O(length).
[[nodiscard]] Result<UtcSeconds> parse_site_time(std::string_view text, double utc_offset_hours);

/// Reads `2026-04-22`. @return the day, or a usage_error naming the text. O(length).
[[nodiscard]] Result<CivilDay> parse_site_date(std::string_view text);

/// @return days since 1970-01-01 of a Gregorian date. @pre month in 1..12, day in 1..31. O(1).
[[nodiscard]] CivilDay civil_day(std::int64_t year, int month, int day);

/// @return `YYYY-MM-DD` of a day. O(1).
[[nodiscard]] std::string format_site_date(CivilDay day);

/// @return the local calendar day, at a UTC offset, that time `t` falls in. O(1).
[[nodiscard]] CivilDay local_day(UtcSeconds t, double utc_offset_hours);

/// @return the UTC time of local midnight starting `day` at a UTC offset. O(1).
[[nodiscard]] UtcSeconds local_midnight(CivilDay day, double utc_offset_hours);

/// @return `HH:MM:SS`, the local clock time of `t` at a UTC offset, rounded to the second;
///         `24:00:00` when it is the midnight that ends `day` (when given). O(1).
[[nodiscard]] std::string format_clock(UtcSeconds t, double utc_offset_hours,
                                       std::optional<CivilDay> day = std::nullopt);

}  // namespace roomcad
