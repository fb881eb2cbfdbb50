// SPDX-License-Identifier: GPL-3.0-or-later
// The sun at one time at a site, as a picture lit by it needs it (`roomcad render --sun`,
// Plan.render(sun=...), the shadow study): where it is and the direction towards it in the
// plan's coordinates.
#pragma once

#include <string>
#include <string_view>

#include "core/error.h"
#include "daylight/sun_position.h"

namespace roomcad {

struct SunAt {
  UtcSeconds time = 0.0;
  SunPosition position;
  Vec3 direction;  ///< unit, towards the sun, plan coordinates (sun_direction_in_plan)
};

/// @return the sun at `time` at `place`, `north_degrees` being the plan's site.north.
///         One sun_position.
[[nodiscard]] SunAt sun_at(const GeoLocation& place, double north_degrees, UtcSeconds time);

/// The same for a time as `roomcad sun --at` reads it (parse_site_time at the place's offset).
/// @return the sun, or a usage_error "`option`: ..." naming the text and the form expected.
[[nodiscard]] Result<SunAt> sun_at(const GeoLocation& place, double north_degrees,
                                   std::string_view time, std::string_view option);

/// @return "2026-03-21 05:00:00 (UTC+3)": a time in the place's local time, for messages. O(1).
[[nodiscard]] std::string site_clock_text(const GeoLocation& place, UtcSeconds time);

}  // namespace roomcad
