// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_compass.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "import/detail/sh3d_walls.h"
#include "import/detail/time_zone.h"

namespace roomcad::sh3d {
namespace {

constexpr std::int64_t kStandardTime = 1767225600;  // 2026-01-01T00:00Z: winter in the north

double degrees(double radians) {
  const double d = radians * 180.0 / std::numbers::pi;
  return std::round(d * 1e4) / 1e4;
}

/// An angle in (-180, 180].
double wrapped(double d) {
  d = std::fmod(d, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d == 0.0 ? 0.0 : d;  // no -0
}

}  // namespace

void place_compass(const std::optional<CompassRecord>& compass,
                   std::optional<std::int64_t> camera_time_ms, Site& site, Report& warnings) {
  if (!compass) return;
  GeoLocation place;
  place.latitude = std::clamp(degrees(compass->latitude), -90.0, 90.0);
  place.longitude = wrapped(degrees(compass->longitude));
  const std::int64_t when = camera_time_ms ? *camera_time_ms / 1000 : kStandardTime;
  if (const std::optional<double> offset = zone_utc_offset(compass->time_zone, when)) {
    place.utc_offset = *offset;
  } else {
    place.utc_offset = std::clamp(std::round(place.longitude / 15.0), -12.0, 14.0);
    Diagnostic d = import_warning(
        Code::import_approximated, "",
        fmt::format("the compass's time zone '{}' is not a zone of this system "
                    "(/usr/share/zoneinfo); the site's utc_offset is the longitude's nearest "
                    "hour, {:+g}",
                    compass->time_zone, place.utc_offset));
    d.objects.clear();
    d.fix = "set the site's UTC offset: roomcad set PLAN site location=LAT,LON,UTC_OFFSET";
    warnings.add(std::move(d));
  }
  site.location = place;
  // Clockwise on the screen from the plan's up is clockwise in roomcad's frame too (the picture
  // is the same); site.north turns counter-clockwise.
  site.north = wrapped(-degrees(compass->north_direction));
}

}  // namespace roomcad::sh3d
