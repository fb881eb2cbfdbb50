// SPDX-License-Identifier: GPL-3.0-or-later
#include "daylight/sun_position.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <utility>

#include <erfa.h>

namespace roomcad {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kJulianUnixEpoch = 2440587.5;  // the Julian date of 1970-01-01T00:00 UTC
/// The sun's equatorial horizontal parallax at 1 au, degrees (IAU: 8.794143 arcseconds).
constexpr double kSolarParallax = 8.794143 / 3600.0;

/// Finds where `f` (continuous) changes sign in [a, b], f(a) and f(b) of opposite signs,
/// to `tolerance`. @return the crossing.
double bisect(const std::function<double(double)>& f, double a, double b, double tolerance) {
  const bool rising = f(a) < 0;
  while (b - a > tolerance) {
    const double m = 0.5 * (a + b);
    ((f(m) < 0) == rising ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace

struct SunTracker::Context {
  eraASTROM astrom{};
};

namespace {

/// A UTC time as ERFA's two-part Julian date.
std::pair<double, double> julian_utc(UtcSeconds t) {
  const double days = std::floor(t / 86400.0);
  return {kJulianUnixEpoch + days, (t - days * 86400.0) / 86400.0};
}

/// The direction from the Earth's centre to the sun at UTC `t` (ICRS right ascension and
/// declination, radians) and its distance in au. Status 1 of ERFA's time scales ("dubious
/// year": before 1960 or past the last leap second it knows) changes TT by under a minute,
/// which moves the sun by under 0.001 degree: used as it is.
struct SunFromEarth {
  double ra = 0, dec = 0, distance = 1;
  double from_sun[3] = {0, 0, 0};  ///< unit vector from the sun to the Earth
};
SunFromEarth sun_from_earth(UtcSeconds t) {
  const auto [utc1, utc2] = julian_utc(t);
  double tai1 = 0, tai2 = 0, tt1 = 0, tt2 = 0;
  eraUtctai(utc1, utc2, &tai1, &tai2);
  eraTaitt(tai1, tai2, &tt1, &tt2);
  double heliocentric[2][3], barycentric[2][3];
  eraEpv00(tt1, tt2, heliocentric, barycentric);  // the Earth, au, BCRS axes
  double to_sun[3];
  eraSxp(-1.0, heliocentric[0], to_sun);
  SunFromEarth out;
  eraC2s(to_sun, &out.ra, &out.dec);
  eraPn(heliocentric[0], &out.distance, out.from_sun);
  return out;
}

}  // namespace

SunTracker::SunTracker(const GeoLocation& place, UtcSeconds from, UtcSeconds to) : from_(from) {
  const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil((to - from) / 3600.0)));
  step_ = std::max((to - from) / static_cast<double>(steps), 1.0);
  for (std::size_t k = 0; k < steps; ++k) {
    auto context = std::make_shared<Context>();
    const auto [utc1, utc2] = julian_utc(from + (static_cast<double>(k) + 0.5) * step_);
    double eo = 0;
    // UT1 taken as UTC; at sea level; pressure 0: no refraction.
    eraApco13(utc1, utc2, 0.0, place.longitude * kDegree, place.latitude * kDegree, 0, 0, 0, 0, 0,
              0, 0.55, &context->astrom, &eo);
    contexts_.push_back(std::move(context));
  }
}

SunPosition SunTracker::at(UtcSeconds t) const {
  SunFromEarth sun = sun_from_earth(t);
  const double k =
      std::clamp(std::floor((t - from_) / step_), 0.0, static_cast<double>(contexts_.size() - 1));
  eraASTROM astrom = contexts_[static_cast<std::size_t>(k)]->astrom;
  const auto [utc1, utc2] = julian_utc(t);
  eraAper13(utc1, utc2, &astrom);  // the Earth's rotation at t
  // The sun's own light is not deflected by the sun: with the Earth's heliocentric direction
  // of the hour instead of t's, eraLdsun would bend it as a star's passing the sun's limb.
  eraCp(sun.from_sun, astrom.eh);
  astrom.em = sun.distance;
  double ri = 0, di = 0, azimuth = 0, zenith = 0, hour_angle = 0, dec = 0, ra = 0;
  // The sun as a source at infinity (aberration and deflection as for a star), so its
  // parallax comes after.
  eraAtciq(sun.ra, sun.dec, 0, 0, 0, 0, &astrom, &ri, &di);
  eraAtioq(ri, di, &astrom, &azimuth, &zenith, &hour_angle, &dec, &ra);
  double elevation = 90.0 - zenith / kDegree;
  elevation -= kSolarParallax / sun.distance * std::cos(elevation * kDegree);
  double degrees = azimuth / kDegree;
  degrees -= 360.0 * std::floor(degrees / 360.0);
  return {degrees >= 360.0 ? 0.0 : degrees, elevation};
}

SunPosition sun_position(const GeoLocation& place, UtcSeconds t) {
  return SunTracker(place, t, t).at(t);
}

std::string_view compass_point(double azimuth) {
  static constexpr std::string_view kPoints[] = {"N", "NNE", "NE", "ENE", "E", "ESE", "SE", "SSE",
                                                 "S", "SSW", "SW", "WSW", "W", "WNW", "NW", "NNW"};
  const double turns = azimuth / 22.5 + 0.5;
  return kPoints[static_cast<int>(std::floor(turns - 16.0 * std::floor(turns / 16.0))) % 16];
}

double azimuth_of_plan_direction(Point2 d, double north_degrees) {
  const double n = north_degrees * kDegree;
  // Undo the turn of sun_direction_in_plan: east and north components.
  const double east = d.x * std::cos(n) + d.y * std::sin(n);
  const double north = -d.x * std::sin(n) + d.y * std::cos(n);
  double degrees = std::atan2(east, north) / kDegree;
  degrees -= 360.0 * std::floor(degrees / 360.0);
  return degrees >= 360.0 ? 0.0 : degrees;
}

Vec3 sun_direction_in_plan(const SunPosition& sun, double north_degrees) {
  const double a = sun.azimuth * kDegree, e = sun.elevation * kDegree;
  const double east = std::sin(a) * std::cos(e), north = std::cos(a) * std::cos(e);
  // True north is +y turned counter-clockwise by `north`, true east is +x turned the same.
  const double n = north_degrees * kDegree;
  return {east * std::cos(n) - north * std::sin(n), east * std::sin(n) + north * std::cos(n),
          std::sin(e)};
}

SunDay sun_day(const GeoLocation& place, CivilDay day) {
  const UtcSeconds start = local_midnight(day, place.utc_offset);
  const SunTracker sun(place, start, start + 86400.0);
  const auto elevation = [&](double t) { return sun.at(t).elevation; };
  constexpr double kStep = 600.0;
  SunDay out;
  double best_t = start, best = elevation(start), previous = best;
  for (double t = start + kStep; t <= start + 86400.0; t += kStep) {
    const double e = elevation(t);
    if ((previous < 0) != (e < 0)) {
      const double crossing = bisect(elevation, t - kStep, t, 0.05);
      if (e >= 0 && !out.sunrise) out.sunrise = crossing;
      if (e < 0) out.sunset = crossing;
    }
    if (e > best) best = e, best_t = t;
    previous = e;
  }
  // The highest elevation, by golden-section search around the best sample.
  double a = std::max(start, best_t - kStep), b = std::min(start + 86400.0, best_t + kStep);
  const double r = (std::sqrt(5.0) - 1.0) / 2.0;
  while (b - a > 0.5) {
    const double c = b - r * (b - a), d = a + r * (b - a);
    if (elevation(c) > elevation(d)) b = d;
    else a = c;
  }
  out.solar_noon = 0.5 * (a + b);
  out.noon_elevation = elevation(out.solar_noon);
  return out;
}

}  // namespace roomcad
