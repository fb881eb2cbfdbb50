// SPDX-License-Identifier: GPL-3.0-or-later
// A Sweet Home 3D compass as the plan's site location and north (plan format version 2): its
// latitude and longitude, its north direction, and its time zone's offset from UTC at the
// moment the home's observer camera shows. The sun is the plan's own, recomputed from these.
#pragma once

#include <cstdint>
#include <optional>

#include "import/detail/sh3d_home.h"
#include "validation/report.h"

namespace roomcad::sh3d {

/// Sets `site.location` and `site.north` from the compass (nothing without one). The offset is
/// the zone's at the camera's time (standard time of the year 2026 without one); a zone the
/// system does not know takes the offset of the longitude's nearest hour, with an
/// import_approximated warning. Angles are rounded to a ten-thousandth of a degree (the file
/// holds single-precision radians, good to about 0.00002 degree). O(zone file).
void place_compass(const std::optional<CompassRecord>& compass,
                   std::optional<std::int64_t> camera_time_ms, Site& site, Report& warnings);

}  // namespace roomcad::sh3d
