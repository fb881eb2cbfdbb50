// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/site_place.h"

#include <fmt/format.h>

namespace roomcad::cli {

void add_place_options(CLI::App& app, PlaceOptions& options) {
  app.add_option("--latitude", options.latitude,
                 "degrees north, -90 to 90 (replaces the plan's site.location)")
      ->type_name("DEG");
  app.add_option("--longitude", options.longitude,
                 "degrees east, -180 to 180 (replaces the plan's site.location)")
      ->type_name("DEG");
  app.add_option("--utc-offset", options.utc_offset,
                 "hours the local time is ahead of UTC, -12 to 14 (default: the plan's, or 0)")
      ->type_name("HOURS");
}

Result<GeoLocation> site_place(const Plan* plan, const std::string& plan_path,
                               const PlaceOptions& options) {
  const bool planned = plan && plan->site.location;
  if (!planned && (!options.latitude || !options.longitude)) {
    const std::string why =
        plan ? fmt::format(
                   "{} does not say where its site is (no site.location); add it with "
                   "`roomcad set {} site location=LAT,LON,UTC_OFFSET`, or give "
                   "--latitude and --longitude",
                   plan_path, plan_path)
             : "give --latitude and --longitude, or a plan whose site has a location";
    return Result<GeoLocation>::failure(Code::usage_error, why);
  }
  GeoLocation place = planned ? *plan->site.location : GeoLocation{};
  if (options.latitude) place.latitude = *options.latitude;
  if (options.longitude) place.longitude = *options.longitude;
  if (options.utc_offset) place.utc_offset = *options.utc_offset;
  const auto out_of = [](std::string_view what, double value, std::string_view range) {
    return Result<GeoLocation>::failure(
        Code::usage_error, fmt::format("{} is {}; it must be in {}", what, value, range));
  };
  if (!(place.latitude >= -90 && place.latitude <= 90))
    return out_of("the latitude", place.latitude, "[-90, 90] degrees");
  if (!(place.longitude >= -180 && place.longitude <= 180))
    return out_of("the longitude", place.longitude, "[-180, 180] degrees");
  if (!(place.utc_offset >= -12 && place.utc_offset <= 14))
    return out_of("the UTC offset", place.utc_offset, "[-12, 14] hours");
  return place;
}

}  // namespace roomcad::cli
