// SPDX-License-Identifier: GPL-3.0-or-later
#include "daylight/sun_at.h"

#include <cmath>

#include <fmt/format.h>

namespace roomcad {

SunAt sun_at(const GeoLocation& place, double north_degrees, UtcSeconds time) {
  const SunPosition position = sun_position(place, time);
  return SunAt{time, position, sun_direction_in_plan(position, north_degrees)};
}

Result<SunAt> sun_at(const GeoLocation& place, double north_degrees, std::string_view time,
                     std::string_view option) {
  const Result<UtcSeconds> t = parse_site_time(time, place.utc_offset);
  if (!t) return Error{Code::usage_error, fmt::format("{}: {}", option, t.error().message)};
  return sun_at(place, north_degrees, t.value());
}

std::string site_clock_text(const GeoLocation& place, UtcSeconds time) {
  const double offset = place.utc_offset;
  const auto day = local_day(time, offset);
  return fmt::format("{} {} (UTC{:+})", format_site_date(day), format_clock(time, offset), offset);
}

}  // namespace roomcad
