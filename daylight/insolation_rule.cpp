// SPDX-License-Identifier: GPL-3.0-or-later
#include "daylight/insolation_rule.h"

#include <algorithm>
#include <cmath>
#include <regex>

#include <fmt/format.h>

#include "core/box.h"

#include "daylight/detail/room_side.h"
#include "daylight/insolation.h"
#include "daylight/sun_position.h"
#include "plan/arc_chords.h"
#include "solid/build_model.h"
#include "validation/room_labels.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

/// Rooms that fall short get fixes computed, up to this many; each costs up to kMaxCandidates
/// builds.
constexpr std::size_t kMaxRoomsFixed = 8;
constexpr std::size_t kMaxCandidates = 10;

CivilDay rule_day(const std::string& text) {
  const bool full = text.size() == 10;
  const int year = full ? std::stoi(text.substr(0, 4)) : kInsolationReferenceYear;
  const std::string md = full ? text.substr(5) : text;
  return civil_day(year, std::stoi(md.substr(0, 2)), std::stoi(md.substr(3)));
}

/// The hours of one window (or room) that count under the rule.
struct Hours {
  double continuous = 0.0;
  double total = 0.0;  ///< of the periods of at least min_period_hours
  std::string window;  ///< "": none
  std::vector<SunInterval> counted;
};

Hours counted_hours(const WindowSun& w, const SunDay& sun, const InsolationRule& rule) {
  const UtcSeconds from =
      sun.sunrise ? *sun.sunrise + rule.ignore_after_sunrise_minutes * 60 : -INFINITY;
  const UtcSeconds to =
      sun.sunset ? *sun.sunset - rule.ignore_before_sunset_minutes * 60 : INFINITY;
  Hours h{0, 0, w.id, {}};
  for (const auto& [a, b] : w.intervals) {
    const double lo = std::max(a, from), hi = std::min(b, to);
    if (hi <= lo) continue;
    h.counted.push_back({lo, hi});
    const double hours = (hi - lo) / 3600.0;
    h.continuous = std::max(h.continuous, hours);
    if (hours >= rule.min_period_hours) h.total += hours;
  }
  return h;
}

bool passes(const Hours& h, const InsolationRule& rule) {
  return h.continuous >= rule.min_continuous_hours ||
         (rule.min_total_hours && h.total >= *rule.min_total_hours);
}

bool better(const Hours& a, const Hours& b) {
  return a.continuous > b.continuous || (a.continuous == b.continuous && a.total > b.total);
}

Hours best_window(const RoomSun& room, const SunDay& sun, const InsolationRule& rule) {
  Hours best;
  for (const WindowSun& w : room.windows)
    if (const Hours h = counted_hours(w, sun, rule); best.window.empty() || better(h, best))
      best = h;
  return best;
}

bool applies(const RoomSun& room, const RuleSet& rules) {
  if (room.area < rules.insolation.min_area) return false;
  if (!rules.insolation.room_pattern.empty())
    return std::regex_search(room.name, std::regex(rules.insolation.room_pattern,
                                                   std::regex::ECMAScript | std::regex::icase));
  return is_habitable_room(Room{room.outline, room.area, room.level, room.walls, {}, {}}, room.name,
                           rules.habitable_rooms);
}

/// A plan as a fix would leave it, the window whose sun decides, and what the fix says.
struct Candidate {
  Plan plan;
  std::string window;
  std::string text;  ///< "moving window 'w' 0.5 m along wall 'a'", ...
};

std::vector<Candidate> candidates(const Plan& plan, const RoomSun& room, const std::string& best,
                                  const std::vector<std::string>& room_walls) {
  std::vector<Candidate> out;
  const auto opening = std::find_if(plan.openings.begin(), plan.openings.end(),
                                    [&](const Opening& o) { return o.id == best; });
  // Its best window moved along its wall, both ways.
  if (opening != plan.openings.end())
    if (const Wall* w = find_wall(plan, opening->wall); w && !w->arc_extent) {
      const double length = std::hypot(w->to.x - w->from.x, w->to.y - w->from.y);
      for (const double d : {-1.0, -0.5, 0.5, 1.0}) {
        if (opening->offset + d < 0 || opening->offset + d + opening->width > length) continue;
        Candidate c{plan, best,
                    fmt::format("moving window '{}' {} m along wall '{}' (towards its {} end)",
                                best, std::fabs(d), w->id, d > 0 ? "`to`" : "`from`")};
        for (Opening& o : c.plan.openings)
          if (o.id == best) o.offset += d;
        out.push_back(std::move(c));
      }
    }
  // A window of the same size (or the format's window) in the middle of another wall.
  const Opening model = opening != plan.openings.end() ? *opening : [] {
    Opening o;
    o.type = OpeningType::window;
    const OpeningDefaults d = opening_defaults(OpeningType::window);
    o.width = d.width, o.height = d.height, o.sill = d.sill;
    return o;
  }();
  std::string id = (best.empty() ? room.room : best) + "-sun";
  while (find_wall(plan, id) || std::any_of(plan.openings.begin(), plan.openings.end(),
                                            [&](const Opening& o) { return o.id == id; }))
    id += "-2";
  for (const std::string& wall_id : room_walls) {
    const Wall* w = find_wall(plan, wall_id);
    if (!w || w->arc_extent || (opening != plan.openings.end() && w->id == opening->wall)) continue;
    const Point2 d{w->to.x - w->from.x, w->to.y - w->from.y};
    const double length = std::hypot(d.x, d.y);
    if (length < model.width + 0.2) continue;
    // The wall's outward side: away from the room.
    const Point2 mid{(w->from.x + w->to.x) / 2, (w->from.y + w->to.y) / 2};
    const Point2 u{d.x / length, d.y / length};
    const double outward = -daylight_detail::room_side(room.outline, mid, u, w->thickness / 2);
    const Point2 n{-u.y * outward, u.x * outward};
    const double azimuth = azimuth_of_plan_direction(n, plan.site.north.value_or(0.0));
    Candidate c{plan, id,
                fmt::format("a window of {} x {} m in the middle of wall '{}' (facing {})",
                            model.width, model.height, w->id, compass_point(azimuth))};
    Opening added = model;
    added.id = id, added.wall = w->id, added.offset = (length - model.width) / 2;
    added.shape.clear();
    added.extra.clear();
    c.plan.openings.push_back(std::move(added));
    out.push_back(std::move(c));
    if (out.size() >= kMaxCandidates) break;
  }
  return out;
}

/// The hours the candidate's window gives the room (same level, same area), or nothing when
/// the candidate adds errors to the plan or the window is not in the room.
std::optional<Hours> hours_with(const Candidate& c, const RoomSun& room, CivilDay day,
                                const SunDay& sun, const RuleSet& rules,
                                std::size_t errors_before) {
  if (validate(c.plan).error_count() > errors_before) return std::nullopt;
  Model model;
  try {
    model = build_model(c.plan);
  } catch (const PreconditionError&) {
    return std::nullopt;
  }
  const InsolationDay result =
      insolation(c.plan, model.walls, day,
                 InsolationOptions{.above_sill = rules.insolation.above_sill,
                                   .into_reveal = rules.insolation.into_reveal,
                                   .only_windows = {c.window}});
  for (const RoomSun& r : result.rooms) {
    if (r.level != room.level || std::fabs(r.area - room.area) > 1e-6) continue;
    for (const WindowSun& w : r.windows)
      if (w.id == c.window) return counted_hours(w, sun, rules.insolation);
  }
  return std::nullopt;
}

std::string describe(const Hours& h, double offset, CivilDay day) {
  if (h.counted.empty()) return "no direct sun";
  std::string spans;
  for (const auto& [a, b] : h.counted)
    spans += fmt::format("{}{}-{}", spans.empty() ? "" : ", ", format_clock(a, offset),
                         format_clock(b, offset, day));
  return fmt::format("{:.2f} h continuous, {:.2f} h in periods that count ({})", h.continuous,
                     h.total, spans);
}

std::string needs(const InsolationRule& rule) {
  std::string text = fmt::format("{:g} h continuous", rule.min_continuous_hours);
  if (rule.min_total_hours)
    text += fmt::format(" or {:g} h in periods of at least {:g} h", *rule.min_total_hours,
                        rule.min_period_hours);
  return text;
}

std::string fix_text(const Plan& plan, const RoomSun& room, const Hours& best,
                     const std::vector<std::string>& walls, CivilDay day, const SunDay& sun,
                     const RuleSet& rules, std::size_t errors_before) {
  std::optional<Hours> top;
  std::string top_text;
  for (const Candidate& c : candidates(plan, room, best.window, walls)) {
    const std::optional<Hours> h = hours_with(c, room, day, sun, rules, errors_before);
    if (h && (!top || better(*h, *top))) top = h, top_text = c.text;
  }
  if (!top || !better(*top, best))
    return best.window.empty()
               ? "no window on one of its walls would get sun (each faces another room or is "
                 "shaded, or would collide with what is there): give it an outside wall"
               : "no move of its window by up to 1 m and no window on another of its walls "
                 "gives it more sun: enlarge its windows upward or clear what shades them";
  return fmt::format("{} gives {:.2f} h continuous, {:.2f} h in all{}", top_text, top->continuous,
                     top->total, passes(*top, rules.insolation) ? "" : " (still short)");
}

}  // namespace

Report check_insolation(const Plan& plan, const SolidMesh& solid, const RuleSet& rules) {
  Report report;
  if (!rules.is_enabled(Code::insolation_short) || !plan.site.location) return report;
  const InsolationRule& rule = rules.insolation;
  const Severity severity = rules.severity[*rule_index(Code::insolation_short)];
  const InsolationOptions options{
      .above_sill = rule.above_sill, .into_reveal = rule.into_reveal, .only_windows = {}};
  // The worst day of the rule for each room: its best window's hours that day.
  struct Shortfall {
    std::size_t room;
    CivilDay day;
    SunDay sun;
    Hours best;
  };
  std::vector<Shortfall> short_rooms;
  std::vector<RoomSun> rooms;
  for (const std::string& date : rule.dates) {
    const CivilDay day = rule_day(date);
    const SunDay sun = sun_day(*plan.site.location, day);
    const InsolationDay result = insolation(plan, solid, day, options);
    if (rooms.empty()) rooms = result.rooms;
    for (std::size_t r = 0; r < result.rooms.size(); ++r) {
      if (!applies(result.rooms[r], rules)) continue;
      const Hours best = best_window(result.rooms[r], sun, rule);
      if (passes(best, rule)) continue;
      auto known = std::find_if(short_rooms.begin(), short_rooms.end(),
                                [&](const Shortfall& s) { return s.room == r; });
      if (known == short_rooms.end()) short_rooms.push_back({r, day, sun, best});
      else if (better(known->best, best)) *known = {r, day, sun, best};
    }
  }
  // A candidate fix may not add errors: counted once, and only when some room falls short.
  const std::size_t errors_before = short_rooms.empty() ? 0 : validate(plan).error_count();
  const double offset = plan.site.location->utc_offset;
  for (std::size_t k = 0; k < short_rooms.size(); ++k) {
    const Shortfall& s = short_rooms[k];
    const RoomSun& room = rooms[s.room];
    const std::vector<std::string>& walls = room.walls;
    const std::string title =
        room.name.empty() ? room.room : fmt::format("{} ({})", room.room, room.name);
    const std::string window = s.best.window.empty()
                                   ? "has no window"
                                   : fmt::format("gets through its best window '{}' {}",
                                                 s.best.window, describe(s.best, offset, s.day));
    Diagnostic d;
    d.severity = severity;
    d.code = Code::insolation_short;
    const auto label = std::find_if(plan.rooms.begin(), plan.rooms.end(),
                                    [&](const RoomLabel& l) { return l.id == room.room; });
    if (label != plan.rooms.end()) d.objects.push_back(label->id);
    if (!s.best.window.empty()) d.objects.push_back(s.best.window);
    else d.objects.insert(d.objects.end(), walls.begin(), walls.end());
    d.message = fmt::format("{}{} on {} {}; the rule asks {}.", title,
                            room.level.empty() ? "" : fmt::format(" on level '{}'", room.level),
                            format_site_date(s.day), window, needs(rule));
    d.fix = k < kMaxRoomsFixed
                ? fix_text(plan, room, s.best, walls, s.day, s.sun, rules, errors_before)
                : "move its windows towards the sun's side, or add one on a wall facing it";
    Box2 box = empty_box2();
    for (const Point2& p : room.outline) add_point(box, p.x, p.y);
    if (!room.outline.empty())
      d.where = Where{{box.min_x, box.min_y}, Point2{box.max_x, box.max_y}};
    report.add(std::move(d));
  }
  return report;
}

void add_insolation_findings(const Plan& plan, const RuleSet& rules, Report& report) {
  if (!rules.is_enabled(Code::insolation_short) || !plan.site.location) return;
  try {
    report.append(check_insolation(plan, build_model(plan).walls, rules));
  } catch (const PreconditionError& e) {
    Diagnostic d;
    d.severity = rules.severity[*rule_index(Code::insolation_short)];
    d.code = Code::insolation_short;
    d.message = "the sun of the plan's rooms could not be checked: its solid cannot be built (" +
                e.error().message + ")";
    d.fix = "clear the plan's errors (`roomcad validate`), then check again";
    report.add(std::move(d));
  }
}

}  // namespace roomcad
