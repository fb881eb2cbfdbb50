// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad shadow-study PLAN --date D [--from HH:MM --to HH:MM --every MIN] -o study.png|DIR/`:
// the model seen from above at times of one day, lit by the sun there, with the shadows of
// the building and its obstructions on the ground; one sheet of labelled panels, or one
// picture a time. Cost: one build, then one render a panel (a shadow map and a frame).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "cli/site_place.h"
#include "daylight/sun_at.h"
#include "io/image_io.h"
#include "plan/plan_levels.h"
#include "render/picture_sheet.h"
#include "render/render_request.h"
#include "render/renderer.h"
#include "solid/build_model.h"

namespace roomcad::cli {
namespace {

/// The most panels one study draws: a day at 15-minute steps.
constexpr int kMaxPanels = 96;

struct StudyOptions {
  std::string plan, date, from, to, output, level;
  int every = 60;  ///< minutes
  int width = 480;
  int shadow_res = 2048;
  int threads = 0;
  PlaceOptions place;
  bool force = false;
  bool verbose = false;
};

/// @return minutes after midnight of "HH:MM" (00:00 to 23:59), or a usage_error naming `flag`.
Result<int> parse_minutes(const std::string& flag, const std::string& text) {
  int h = -1, m = -1;
  char colon = 0;
  std::size_t used = 0;
  if (std::sscanf(text.c_str(), "%2d%c%2d%zn", &h, &colon, &m, &used) != 3 || colon != ':' ||
      used != text.size() || text.size() != 5 || h < 0 || h > 23 || m < 0 || m > 59)
    return Error{
        Code::usage_error,
        fmt::format("{} '{}': expected a local time of day HH:MM, 00:00 to 23:59", flag, text)};
  return h * 60 + m;
}

/// The span of the study in minutes after local midnight: --from and --to, or by default the
/// sun's day rounded inwards to the hour (08:00 to 18:00 when the sun neither rises nor sets).
struct Span {
  int from = 8 * 60, to = 18 * 60;
};

Result<Span> study_span(const StudyOptions& o, const GeoLocation& place, CivilDay day) {
  Span span;
  const SunDay sun = sun_day(place, day);
  const UtcSeconds midnight = local_midnight(day, place.utc_offset);
  if (sun.sunrise && sun.sunset) {
    span.from = static_cast<int>(std::ceil((*sun.sunrise - midnight) / 3600.0)) * 60;
    span.to = static_cast<int>(std::floor((*sun.sunset - midnight) / 3600.0)) * 60;
    span.from = std::clamp(span.from, 0, 23 * 60);
    span.to = std::clamp(span.to, span.from, 23 * 60);
  }
  if (!o.from.empty()) {
    const Result<int> from = parse_minutes("--from", o.from);
    if (!from) return from.error();
    span.from = from.value();
  }
  if (!o.to.empty()) {
    const Result<int> to = parse_minutes("--to", o.to);
    if (!to) return to.error();
    span.to = to.value();
  }
  if (span.to < span.from)
    return Error{Code::usage_error,
                 fmt::format("--to {:02}:{:02} is before --from {:02}:{:02}", span.to / 60,
                             span.to % 60, span.from / 60, span.from % 60)};
  return span;
}

/// The checked request: where, when, which times, and where the pictures go.
struct Study {
  GeoLocation place;
  CivilDay day = 0;
  std::vector<int> minutes;  ///< the panels' times, minutes after local midnight
  bool to_directory = false;
};

Result<Study> plan_study(const StudyOptions& o, const Plan& plan) {
  Study s;
  const Result<GeoLocation> place = site_place(&plan, o.plan, o.place);
  if (!place) return place.error();
  s.place = place.value();
  const Result<CivilDay> day = parse_site_date(o.date);
  if (!day) return Error{Code::usage_error, "--date: " + day.error().message};
  s.day = day.value();
  if (o.every <= 0)
    return Error{Code::usage_error,
                 fmt::format("--every {}: the minutes between panels must be positive", o.every)};
  const Result<Span> span = study_span(o, s.place, s.day);
  if (!span) return span.error();
  const int count = (span->to - span->from) / o.every + 1;
  if (count > kMaxPanels)
    return Error{Code::usage_error,
                 fmt::format("--from {:02}:{:02} --to {:02}:{:02} --every {} makes {} panels; at "
                             "most {} are drawn (raise --every or narrow the span)",
                             span->from / 60, span->from % 60, span->to / 60, span->to % 60,
                             o.every, count, kMaxPanels)};
  for (int k = 0; k < count; ++k) s.minutes.push_back(span->from + k * o.every);
  const std::filesystem::path out(o.output);
  s.to_directory = o.output.ends_with('/') || std::filesystem::is_directory(out);
  if (!s.to_directory && out.extension() != ".png")
    return Error{Code::usage_error,
                 fmt::format("-o '{}': expected a .png file, or a directory (ending in '/') for "
                             "one picture a time",
                             o.output)};
  return s;
}

/// The view from above: the model and its obstructions with a quarter of their size around
/// them, where the shadows fall.
Camera top_camera(const Model& model, const Plan& plan) {
  Box3 box = empty_box3();
  for (const SolidMesh* mesh : {&model.walls, &model.floor, &model.fixtures})
    for (const auto v : mesh->vertices()) {
      const auto& p = mesh->point(v);
      add_point(box, p[0], p[1], p[2]);
    }
  for (const Obstruction& o : plan.obstructions)
    for (const Point2& p : o.outline) add_point(box, p.x, p.y, o.base + o.height);
  if (is_empty(box)) add_point(box, 0.0, 0.0, 0.0);
  const double margin = 0.25 * std::max({box.high[0] - box.low[0], box.high[1] - box.low[1], 1.0});
  for (const std::size_t k : {0u, 1u}) {
    box.low[k] -= margin;
    box.high[k] += margin;
  }
  return frame_view(box, ViewPreset::top, Projection::orthographic, 50.0, 1.0);
}

/// "08:00  AZ 123.4°  EL 45.6°", or the sun below the horizon.
std::string caption(int minutes, const SunAt& sun) {
  const std::string clock = fmt::format("{:02}:{:02}", minutes / 60, minutes % 60);
  if (sun.position.elevation <= 0)
    return fmt::format("{}  SUN DOWN, SKY ALONE (EL {:.1f}°)", clock, sun.position.elevation);
  return fmt::format("{}  AZ {:.1f}°  EL {:.1f}°", clock, sun.position.azimuth,
                     sun.position.elevation);
}

std::string sheet_title(const StudyOptions& o, const Study& s) {
  std::string title = fmt::format("SHADOWS {}  {:.4f}{} {:.4f}{}  UTC{:+}", format_site_date(s.day),
                                  std::fabs(s.place.latitude), s.place.latitude < 0 ? "S" : "N",
                                  std::fabs(s.place.longitude), s.place.longitude < 0 ? "W" : "E",
                                  s.place.utc_offset);
  if (!o.level.empty()) title.append("  LEVEL ").append(o.level);
  return title;
}

int run_shadow_study(const StudyOptions& o) {
  const Result<LoadedPlan> loaded =
      load_valid_plan("shadow-study", o.plan, o.force, findings_for(o.verbose));
  if (!loaded) return exit_status_of(loaded.code());
  const Result<Study> study = plan_study(o, loaded->plan);
  if (!study) return report_failure("shadow-study", study.error());
  const Result<Plan> level = select_level(loaded->plan, o.level);
  if (!level) return report_failure("shadow-study", level.error());
  const Plan& plan = level.value();
  RenderRequest request;
  request.width = request.height = o.width;
  request.shadow_res = o.shadow_res;
  request.threads = o.threads;
  request.grid = "off";
  request.sun = Vec3{0, 0, 1};  // checked here; each panel's sun is set below
  Result<RenderOptions> checked = make_render_options(request, plan);
  if (!checked) return report_failure("shadow-study", checked.error());
  const Model model =
      build_model(plan, BuildOptions{.parts = checked->parts, .threads = o.threads});
  const Camera camera = top_camera(model, plan);
  const double north = plan.site.north.value_or(0.0);
  const UtcSeconds midnight = local_midnight(study->day, study->place.utc_offset);
  std::vector<RgbImage> panels;
  for (const int minutes : study->minutes) {
    const SunAt sun = sun_at(study->place, north, midnight + 60.0 * minutes);
    request.sun = sun.direction;
    RenderOptions options = make_render_options(request, plan).value();
    options.camera = camera;
    options.outputs = FrameOutputs{.depth = false, .object_ids = false};
    FrameBuffers out;
    render_model(model, options, out);
    panels.push_back(add_caption(out.color, caption(minutes, sun)));
  }
  if (!study->to_directory) {
    if (const Status s = write_png(lay_out_sheet(panels, sheet_title(o, *study)), o.output); !s)
      return report_failure("shadow-study", s.error());
    return kExitOk;
  }
  std::error_code made;
  std::filesystem::create_directories(o.output, made);
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const int m = study->minutes[k];
    const auto path =
        std::filesystem::path(o.output) / fmt::format("study-{:02}{:02}.png", m / 60, m % 60);
    if (const Status s = write_png(panels[k], path); !s)
      return report_failure("shadow-study", s.error());
  }
  return kExitOk;
}

}  // namespace

void add_shadow_study_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<StudyOptions>();
  CLI::App* app = root.add_subcommand(
      "shadow-study",
      "The model seen from above at times of one day, lit by the sun at the site, with the\n"
      "shadows of the building and of the plan's obstructions on the ground: one sheet of\n"
      "panels labelled with the time and the sun's azimuth and elevation, or one picture a\n"
      "time (-o DIR/). The site is the plan's site.location, or --latitude and --longitude.");
  app->add_option("PLAN", options->plan, "the plan file (JSON)")->required()->type_name("FILE");
  app->add_option("--date", options->date, "the day, local at the site, YYYY-MM-DD")
      ->required()
      ->type_name("DATE");
  app->add_option("--from", options->from,
                  "first panel's local time HH:MM (default: sunrise, rounded up to the hour; "
                  "08:00 in polar day or night)")
      ->type_name("HH:MM");
  app->add_option("--to", options->to,
                  "last panel's time at most, HH:MM (default: sunset, rounded down to the hour; "
                  "18:00 in polar day or night)")
      ->type_name("HH:MM");
  app->add_option("--every", options->every, "minutes between panels")
      ->capture_default_str()
      ->type_name("MIN");
  app->add_option("-o,--output", options->output,
                  "the sheet (.png), or a directory (ending in '/', or existing): one picture a "
                  "time, study-HHMM.png")
      ->required();
  app->add_option("--width", options->width, "pixels a side of a panel")
      ->check(CLI::Range(64, 4096))
      ->capture_default_str();
  app->add_option("--shadow-res", options->shadow_res, "shadow-map texels per side")
      ->check(CLI::Range(1, kMaxShadowResolution))
      ->capture_default_str();
  app->add_option("--level", options->level,
                  "show this level alone (its walls, openings and slabs): its floor with the "
                  "shadows falling on it");
  add_place_options(*app, options->place);
  app->add_option("--threads", options->threads,
                  "threads, 0 = all cores (the same pictures at any count)")
      ->check(CLI::Range(0, kMaxThreads));
  app->add_flag("--force", options->force, "draw even if the plan has validation errors");
  add_verbose_flag(*app, options->verbose);
  commands.push_back({app, [options] { return run_shadow_study(*options); }});
}

}  // namespace roomcad::cli
