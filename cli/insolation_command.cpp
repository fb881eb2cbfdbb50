// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad insolation PLAN --date YYYY-MM-DD [--format json]`: the direct sun each room's
// windows get that day (docs/plan-format.md, "Sun and sunlight"; daylight/insolation.h).
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/json_text.h"
#include "cli/plan_loading.h"
#include "cli/site_place.h"
#include "daylight/insolation.h"
#include "io/rule_set_file.h"
#include "solid/build_model.h"

namespace roomcad::cli {
namespace {

struct InsolationCommandOptions {
  std::string plan;
  std::string date;
  std::string rules;
  PlaceOptions place;
  std::string format = "text";
  int threads = 0;
  bool force = false;
  bool verbose = false;
};

std::string intervals_json(const WindowSun& w, const InsolationDay& day) {
  std::string out = "[";
  for (const auto& [a, b] : w.intervals)
    out += fmt::format("{}[\"{}\", \"{}\"]", out.size() > 1 ? ", " : "",
                       format_clock(a, day.place.utc_offset),
                       format_clock(b, day.place.utc_offset, day.date));
  return out + "]";
}

void print_json(const InsolationDay& day) {
  std::string out = fmt::format(
      "{{\"date\": \"{}\", \"utc_offset\": {}, \"latitude\": {}, "
      "\"longitude\": {}, \"rooms\": [",
      format_site_date(day.date), day.place.utc_offset, day.place.latitude, day.place.longitude);
  for (std::size_t r = 0; r < day.rooms.size(); ++r) {
    const RoomSun& room = day.rooms[r];
    out += fmt::format(
        "{}\n  {{\"room\": {}, \"name\": {}, \"level\": {}, \"area\": {:.2f}, "
        "\"windows\": [",
        r ? "," : "", json_string(room.room), json_string(room.name), json_string(room.level),
        room.area);
    for (std::size_t i = 0; i < room.windows.size(); ++i) {
      const WindowSun& w = room.windows[i];
      out += fmt::format(
          "{}{{\"id\": {}, \"intervals\": {}, \"continuous_hours\": {:.4f}, "
          "\"total_hours\": {:.4f}}}",
          i ? ", " : "", json_string(w.id), intervals_json(w, day), w.continuous_hours,
          w.total_hours);
    }
    out += fmt::format(
        "], \"best_window\": {}, \"continuous_hours\": {:.4f}, "
        "\"total_hours\": {:.4f}}}",
        room.best_window.empty() ? "null" : json_string(room.best_window), room.continuous_hours,
        room.total_hours);
  }
  out += "\n]}\n";
  std::fputs(out.c_str(), stdout);
}

void print_text(const InsolationDay& day) {
  std::printf("direct sun on %s at %.4f, %.4f (UTC%+g)\n", format_site_date(day.date).c_str(),
              day.place.latitude, day.place.longitude, day.place.utc_offset);
  for (const RoomSun& room : day.rooms) {
    const std::string title =
        room.name.empty() ? room.room : fmt::format("{} ({})", room.room, room.name);
    const std::string level = room.level.empty() ? "" : fmt::format(", level {}", room.level);
    if (room.windows.empty()) {
      std::printf("%s%s, %.1f m²: no window\n", title.c_str(), level.c_str(), room.area);
      continue;
    }
    std::printf("%s%s, %.1f m²: %.2f h continuous, %.2f h in all (window %s)\n", title.c_str(),
                level.c_str(), room.area, room.continuous_hours, room.total_hours,
                room.best_window.c_str());
    for (const WindowSun& w : room.windows) {
      std::string spans;
      for (const auto& [a, b] : w.intervals)
        spans +=
            fmt::format("{}{}-{}", spans.empty() ? "" : ", ", format_clock(a, day.place.utc_offset),
                        format_clock(b, day.place.utc_offset, day.date));
      std::printf("  window %s: %s\n", w.id.c_str(), spans.empty() ? "no sun" : spans.c_str());
    }
  }
}

int run_insolation(const InsolationCommandOptions& options) {
  const Result<CivilDay> date = parse_site_date(options.date);
  if (!date)
    return report_failure("insolation",
                          Error{Code::usage_error, "--date: " + date.error().message});
  InsolationOptions computing{.threads = options.threads};
  if (!options.rules.empty()) {
    const Result<RuleSet> rules = load_rule_set(options.rules, "--rules");
    if (!rules) return report_failure("insolation", rules.error());
    computing.above_sill = rules.value().insolation.above_sill;
    computing.into_reveal = rules.value().insolation.into_reveal;
  }
  Result<LoadedPlan> loaded =
      load_valid_plan("insolation", options.plan, options.force, findings_for(options.verbose));
  if (!loaded) return exit_status_of(loaded.code());
  Plan& plan = loaded.value().plan;
  const Result<GeoLocation> place = site_place(&plan, options.plan, options.place);
  if (!place) return report_failure("insolation", place.error());
  plan.site.location = place.value();
  BuildOptions build;
  build.threads = options.threads;
  const Model model = build_model(plan, build);
  const InsolationDay day = insolation(plan, model.walls, date.value(), computing);
  if (options.format == "json") print_json(day);
  else print_text(day);
  return kExitOk;
}

}  // namespace

void add_insolation_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<InsolationCommandOptions>();
  CLI::App* app = root.add_subcommand(
      "insolation",
      "Direct sun room by room on one day: for every room and each window in its walls, the\n"
      "intervals (local time) when the sun reaches the window's calculation point (the middle\n"
      "of its width, on the room-side face of its wall, at the sill) unblocked by walls,\n"
      "slabs, the window's own reveals and the plan's obstructions; the longest and the total.\n"
      "A room's figures are its best window's. Interval ends are found to the second.");
  app->add_option("PLAN", options->plan, "the plan file (JSON), with site.location")
      ->required()
      ->type_name("FILE");
  app->add_option("--date", options->date, "the day, local at the site")
      ->required()
      ->type_name("YYYY-MM-DD");
  app->add_option("--rules", options->rules,
                  "a rules file whose insolation_short settings move the calculation point "
                  "(above_sill, into_reveal)")
      ->type_name("FILE");
  add_place_options(*app, options->place);
  add_format_option(*app, options->format);
  app->add_option("--threads", options->threads, "worker threads, 0 for all cores")
      ->capture_default_str();
  app->add_flag("--force", options->force, "compute even if validation finds errors");
  add_verbose_flag(*app, options->verbose);
  commands.push_back({app, [options] { return run_insolation(*options); }});
}

}  // namespace roomcad::cli
