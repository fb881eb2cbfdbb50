// SPDX-License-Identifier: GPL-3.0-or-later
// Where the sun is, seen from a place on the Earth at a time: its azimuth and geometric
// elevation, and that direction in a plan's coordinates.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "daylight/site_time.h"
#include "plan/plan.h"

namespace roomcad {

/// The sun's centre seen from a place, topocentric, without refraction.
struct SunPosition {
  double azimuth = 0.0;    ///< degrees clockwise from true north, [0, 360)
  double elevation = 0.0;  ///< degrees above the horizon (geometric), [-90, 90]
};

/// @return the sun's position at `place` (latitude and longitude; its utc_offset is not used)
///         at time `t`. The IAU 2006/2000A chain of ERFA: the Earth's position (VSOP2000-based
///         eraEpv00), aberration, precession-nutation and Earth rotation (UT1 taken as UTC),
///         plus the sun's parallax; refraction off. Agrees with python3-ephem within 0.01
///         degree over 1950-2100 (tests/python/test_sun.py, 1,000 random places and times).
///         Cost: the whole chain each call; SunTracker shares its slow part between the times
///         of a span (bench/report.md, "Daylight", has both costs).
[[nodiscard]] SunPosition sun_position(const GeoLocation& place, UtcSeconds t);

/// Sun positions at one place over a span of time, cheaply: the slow parts of the chain
/// (precession-nutation, the Earth's position and velocity for deflection and aberration) are
/// computed once per hour of the span, and only the Earth's position and rotation per time.
/// Within the span it agrees with sun_position within 0.0002 degree (a test checks it).
/// Immutable: positions may be asked from any thread.
class SunTracker {
 public:
  /// @pre from <= to
  SunTracker(const GeoLocation& place, UtcSeconds from, UtcSeconds to);
  [[nodiscard]] SunPosition at(UtcSeconds t) const;

 private:
  struct Context;  // ERFA's astrometry context, kept out of this header
  UtcSeconds from_ = 0;
  double step_ = 1;
  std::vector<std::shared_ptr<const Context>> contexts_;  ///< one per step of the span
};

/// @return "N", "NNE", ..., "NNW": the nearest of the 16 points of the compass to an azimuth in
///         degrees clockwise from north. O(1).
[[nodiscard]] std::string_view compass_point(double azimuth);

/// @return the azimuth (degrees clockwise from true north, [0, 360)) of a horizontal direction
///         (x, y) in plan coordinates, `site.north` degrees counter-clockwise from +y being
///         true north. O(1).
[[nodiscard]] double azimuth_of_plan_direction(Point2 direction, double north_degrees);

/// @return the unit vector from the plan towards the sun, in plan coordinates (x, y across,
///         z up): `site.north` degrees counter-clockwise from +y is true north. O(1).
[[nodiscard]] Vec3 sun_direction_in_plan(const SunPosition& sun, double north_degrees);

/// The sun's day at a place: when its centre's geometric elevation crosses 0, and when it is
/// highest.
struct SunDay {
  std::optional<UtcSeconds> sunrise;  ///< nothing in polar day or night
  UtcSeconds solar_noon = 0.0;
  std::optional<UtcSeconds> sunset;  ///< nothing in polar day or night
  double noon_elevation = 0.0;       ///< degrees, at solar_noon
};

/// @return the sunrise, solar noon and sunset of the local calendar day `day` (at the place's
///         utc_offset): the first rise and the last set within it, each to a tenth of a second
///         (bisection from a 10-minute scan), and the highest elevation to a second. A rise or
///         set that the scan steps over (a graze shorter than 10 minutes) is missed.
///         About 200 sun positions.
[[nodiscard]] SunDay sun_day(const GeoLocation& place, CivilDay day);

}  // namespace roomcad
