// SPDX-License-Identifier: GPL-3.0-or-later
// Where the site of a sun command is: the plan's `site.location`, or --latitude, --longitude
// and --utc-offset given on the command line (which also replace the plan's), shared by
// `sun`, `insolation`, `render --sun` and `shadow-study`.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad::cli {

/// The place options of a command.
struct PlaceOptions {
  std::optional<double> latitude;
  std::optional<double> longitude;
  std::optional<double> utc_offset;
};

/// Adds --latitude, --longitude and --utc-offset to a command.
void add_place_options(CLI::App& app, PlaceOptions& options);

/// @return the place: `plan`'s location (when there is a plan and it has one) with the options
///         given replacing its fields; or a usage_error naming what is missing (a plan without
///         `site.location` and no --latitude/--longitude: how to add one) or out of range.
///         `plan_path` names the plan in messages.
[[nodiscard]] Result<GeoLocation> site_place(const Plan* plan, const std::string& plan_path,
                                             const PlaceOptions& options);

}  // namespace roomcad::cli
