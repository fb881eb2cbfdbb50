// SPDX-License-Identifier: GPL-3.0-or-later
// The sun's position: the day tracker against the full chain, the direction in a plan turned
// from north, and the days of the poles. (tests/python/test_sun.py checks the positions against
// python3-ephem.)
#include <cmath>

#include <gtest/gtest.h>

#include "daylight/sun_position.h"

namespace roomcad {
namespace {

constexpr GeoLocation kMoscow{55.75, 37.62, 3, {}};

TEST(SunPosition, TheTrackerAgreesWithTheFullChainOverADay) {
  const UtcSeconds noon = parse_site_time("2026-04-22T12:00", 3).value();
  const SunTracker tracker(kMoscow, noon - 43200, noon + 43200);
  double worst = 0;
  for (double dt = -43200; dt <= 43200; dt += 600) {
    const SunPosition a = tracker.at(noon + dt), b = sun_position(kMoscow, noon + dt);
    worst = std::max(worst, std::fabs(a.elevation - b.elevation));
    worst = std::max(worst, std::fabs(a.azimuth - b.azimuth) * std::cos(b.elevation * M_PI / 180));
  }
  EXPECT_LT(worst, 2e-4);
}

TEST(SunPosition, TheDirectionTurnsWithNorth) {
  const SunPosition south_east{135.0, 30.0};
  const Vec3 d = sun_direction_in_plan(south_east, 0);
  const double h = std::cos(30.0 * M_PI / 180) / std::sqrt(2.0);
  EXPECT_NEAR(d.x, h, 1e-12);   // east
  EXPECT_NEAR(d.y, -h, 1e-12);  // south
  EXPECT_NEAR(d.z, 0.5, 1e-12);
  const Vec3 turned = sun_direction_in_plan(south_east, 90);  // true north is -x
  EXPECT_NEAR(turned.x, h, 1e-12);
  EXPECT_NEAR(turned.y, h, 1e-12);
}

TEST(SunPosition, NoonIsHighestAndSunriseAndSunsetAreAtTheHorizon) {
  const SunDay day = sun_day(kMoscow, civil_day(2026, 4, 22));
  ASSERT_TRUE(day.sunrise && day.sunset);
  EXPECT_NEAR(sun_position(kMoscow, *day.sunrise).elevation, 0, 0.005);
  EXPECT_NEAR(sun_position(kMoscow, *day.sunset).elevation, 0, 0.005);
  EXPECT_GT(day.noon_elevation, sun_position(kMoscow, day.solar_noon - 60).elevation);
  EXPECT_GT(day.noon_elevation, sun_position(kMoscow, day.solar_noon + 60).elevation);
  EXPECT_LT(*day.sunrise, day.solar_noon);
  EXPECT_LT(day.solar_noon, *day.sunset);
}

TEST(SunPosition, PolarDayAndNightHaveNoSunriseOrSunset) {
  const GeoLocation svalbard{78.2, 15.6, 1, {}};
  for (const CivilDay d : {civil_day(2026, 6, 21), civil_day(2026, 12, 21)}) {
    const SunDay day = sun_day(svalbard, d);
    EXPECT_FALSE(day.sunrise);
    EXPECT_FALSE(day.sunset);
  }
  EXPECT_GT(sun_day(svalbard, civil_day(2026, 6, 21)).noon_elevation, 0);
  EXPECT_LT(sun_day(svalbard, civil_day(2026, 12, 21)).noon_elevation, 0);
}

}  // namespace
}  // namespace roomcad
