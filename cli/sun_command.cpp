// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad sun [PLAN] --at TIME [--latitude D --longitude D --utc-offset H] [--format json]`:
// where the sun is at the site (docs/plan-format.md, "Sun and sunlight").
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "cli/site_place.h"
#include "daylight/sun_position.h"

namespace roomcad::cli {
namespace {

struct SunOptions {
  std::string plan;
  std::string at;
  PlaceOptions place;
  std::string format = "text";
};

std::string json_clock(const std::optional<UtcSeconds>& t, double offset) {
  return t ? fmt::format("\"{}\"", format_clock(*t, offset)) : "null";
}

int run_sun(const SunOptions& options) {
  std::optional<LoadedPlan> loaded;
  if (!options.plan.empty()) {
    Result<LoadedPlan> read = load_plan("sun", options.plan, Findings::counted);
    if (!read) return exit_status_of(read.error().code);
    loaded = std::move(read).value();
  }
  const Plan* plan = loaded ? &loaded->plan : nullptr;
  const Result<GeoLocation> place = site_place(plan, options.plan, options.place);
  if (!place) return report_failure("sun", place.error());
  const double offset = place.value().utc_offset;
  const Result<UtcSeconds> at = parse_site_time(options.at, offset);
  if (!at) return report_failure("sun", Error{Code::usage_error, "--at: " + at.error().message});
  const SunPosition sun = sun_position(place.value(), at.value());
  const double north = plan ? plan->site.north.value_or(0.0) : 0.0;
  const Vec3 d = sun_direction_in_plan(sun, north);
  const auto day = local_day(at.value(), offset);
  const SunDay sun_day_ = sun_day(place.value(), day);
  if (options.format == "json") {
    std::printf(
        "{\"at\": \"%sT%s\", \"latitude\": %.6f, \"longitude\": %.6f, \"utc_offset\": %g, "
        "\"azimuth\": %.6f, \"elevation\": %.6f, \"direction\": [%.9f, %.9f, %.9f], "
        "\"sunrise\": %s, \"solar_noon\": \"%s\", \"sunset\": %s}\n",
        format_site_date(day).c_str(), format_clock(at.value(), offset).c_str(),
        place.value().latitude, place.value().longitude, offset, sun.azimuth, sun.elevation, d.x,
        d.y, d.z, json_clock(sun_day_.sunrise, offset).c_str(),
        format_clock(sun_day_.solar_noon, offset).c_str(),
        json_clock(sun_day_.sunset, offset).c_str());
    return kExitOk;
  }
  const GeoLocation& p = place.value();
  std::printf("sun at %s %s (UTC%+g), %.4f° %s, %.4f° %s\n", format_site_date(day).c_str(),
              format_clock(at.value(), offset).c_str(), offset, std::fabs(p.latitude),
              p.latitude < 0 ? "S" : "N", std::fabs(p.longitude), p.longitude < 0 ? "W" : "E");
  std::printf("  azimuth %.2f° (%s), elevation %.2f°%s\n", sun.azimuth,
              std::string(compass_point(sun.azimuth)).c_str(), sun.elevation,
              sun.elevation < 0 ? " (below the horizon)" : "");
  std::printf("  towards the sun in plan coordinates: %.4f, %.4f, %.4f (north %g° from +y)\n", d.x,
              d.y, d.z, north);
  const auto clock = [&](const std::optional<UtcSeconds>& t, const char* none) {
    return t ? format_clock(*t, offset) : std::string(none);
  };
  const char* polar = sun_day_.noon_elevation > 0 ? "none (polar day)" : "none (polar night)";
  std::printf("  sunrise %s, solar noon %s (%.2f°), sunset %s\n",
              clock(sun_day_.sunrise, polar).c_str(),
              format_clock(sun_day_.solar_noon, offset).c_str(), sun_day_.noon_elevation,
              clock(sun_day_.sunset, polar).c_str());
  return kExitOk;
}

}  // namespace

void add_sun_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<SunOptions>();
  CLI::App* app = root.add_subcommand(
      "sun",
      "Where the sun is at a site and time: its azimuth (degrees clockwise from true north),\n"
      "its elevation (geometric, no refraction), the direction towards it in the plan's\n"
      "coordinates (site.north applied), and that day's sunrise, solar noon and sunset in\n"
      "the site's local time. The site is the plan's site.location, or --latitude and\n"
      "--longitude without a plan.");
  app->add_option("PLAN", options->plan, "a plan whose site has a location (optional)")
      ->type_name("FILE");
  app->add_option("--at", options->at,
                  "local time at the site, YYYY-MM-DDTHH:MM[:SS], or with its own offset "
                  "(Z, +03:00)")
      ->required()
      ->type_name("TIME");
  add_place_options(*app, options->place);
  add_format_option(*app, options->format);
  commands.push_back({app, [options] { return run_sun(*options); }});
}

}  // namespace roomcad::cli
