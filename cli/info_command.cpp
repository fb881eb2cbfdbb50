// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad info PLAN [--format text|json]`: what a plan holds and how big it is.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/command.h"
#include "cli/json_text.h"
#include "cli/plan_loading.h"
#include "validation/room_labels.h"
#include "validation/validate.h"

namespace roomcad::cli {
namespace {

struct InfoOptions {
  std::string plan;
  std::string format = "text";
};

struct Box3 {
  Vec3 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};
  void add(double x, double y, double z) {
    min = {std::min(min.x, x), std::min(min.y, y), std::min(min.z, z)};
    max = {std::max(max.x, x), std::max(max.y, y), std::max(max.z, z)};
  }
};

struct PlanInfo {
  std::size_t doors = 0;
  std::size_t windows = 0;
  double total_wall_length = 0.0;
  double max_wall_height = 0.0;
  std::optional<Box3> bounds;     ///< of the walls' footprints, base to top
  std::vector<LevelRooms> rooms;  ///< closed regions of the walls, level by level, with their
                                  ///< clear floor areas
};

/// A wall's centre line seen from one of its ends: that end, the unit direction away from it,
/// and half the thickness.
struct WallEndView {
  Point2 at;
  double dx, dy;
  double half;
};

/// Where side `side_a` of wall a (+1 left, -1 right, seen leaving `a.at`) crosses side
/// `side_b` of wall b, which leaves the same point; nothing when the walls are parallel.
std::optional<Point2> side_crossing(const WallEndView& a, double side_a, const WallEndView& b,
                                    double side_b) {
  const Point2 pa{a.at.x - a.dy * a.half * side_a, a.at.y + a.dx * a.half * side_a};
  const Point2 pb{b.at.x - b.dy * b.half * side_b, b.at.y + b.dx * b.half * side_b};
  const double cross = a.dx * b.dy - a.dy * b.dx;
  if (std::abs(cross) < 1e-12) return std::nullopt;
  const double t = ((pb.x - pa.x) * b.dy - (pb.y - pa.y) * b.dx) / cross;
  return Point2{pa.x + t * a.dx, pa.y + t * a.dy};
}

/// Counts and measures. The bounds are those of the wall footprints: each wall's rectangle,
/// and at an end point shared by exactly two walls, the two corners of their mitre.
PlanInfo measure(const Plan& plan) {
  PlanInfo info;
  for (const Opening& o : plan.openings)
    (o.type == OpeningType::door ? info.doors : info.windows)++;
  std::vector<std::pair<WallEndView, const Wall*>> ends;
  for (const Wall& w : plan.walls) {
    const double dx = w.to.x - w.from.x;
    const double dy = w.to.y - w.from.y;
    const double length = std::hypot(dx, dy);
    info.total_wall_length += length;
    info.max_wall_height = std::max(info.max_wall_height, w.height);
    if (!info.bounds) info.bounds.emplace();
    const double lo = w.base;
    const double hi = w.base + w.height;
    // Half-thickness offset along the left normal; a zero-length wall is just its point.
    const double nx = length > 0 ? -dy / length * w.thickness / 2 : 0.0;
    const double ny = length > 0 ? dx / length * w.thickness / 2 : 0.0;
    for (const Point2& p : {w.from, w.to}) {
      for (double side : {-1.0, 1.0}) {
        info.bounds->add(p.x + side * nx, p.y + side * ny, lo);
        info.bounds->add(p.x + side * nx, p.y + side * ny, hi);
      }
    }
    if (length > 0) {
      ends.push_back({{w.from, dx / length, dy / length, w.thickness / 2}, &w});
      ends.push_back({{w.to, -dx / length, -dy / length, w.thickness / 2}, &w});
    }
  }
  std::sort(ends.begin(), ends.end(), [](const auto& a, const auto& b) {
    return std::pair(a.first.at.x, a.first.at.y) < std::pair(b.first.at.x, b.first.at.y);
  });
  for (std::size_t i = 0; i < ends.size();) {
    std::size_t j = i;
    while (j < ends.size() && ends[j].first.at == ends[i].first.at) ++j;
    if (j - i == 2) {  // a mitred corner
      const auto& [a, wa] = ends[i];
      const auto& [b, wb] = ends[i + 1];
      for (double side : {-1.0, 1.0}) {
        if (const auto corner = side_crossing(a, side, b, -side)) {
          info.bounds->add(corner->x, corner->y, std::max(wa->base, wb->base));
        }
      }
    }
    i = j;
  }
  info.rooms = find_rooms_by_level(plan);
  return info;
}

/// A length for people: millimetre precision, no trailing zeros.
std::string metres(double x) {
  if (!std::isfinite(x)) return fmt::format("{}", x);
  std::string s = fmt::format("{:.3f}", x);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string json_strings(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + json_string(items[i]);
  return out + ']';
}

/// `"rooms": [...]`: name, level (in a plan with levels), clear floor area (m^2) and the walls,
/// doors and windows of each. Rooms are numbered level by level, as validation names them.
std::string json_rooms(const std::vector<LevelRooms>& levels) {
  std::string out = "  \"rooms\": [";
  bool first = true;
  for (const LevelRooms& l : levels)
    for (std::size_t i = 0; i < l.rooms.size(); ++i, first = false) {
      const Room& r = l.rooms[i];
      out += fmt::format(
          "{}\n    {{\"name\": \"room {}\", {}\"area\": {}, \"walls\": {}, \"doors\": {}, "
          "\"windows\": {}}}",
          first ? "" : ",", i + 1,
          l.level.empty() ? "" : fmt::format("\"level\": {}, ", json_string(l.level)),
          json_number(r.area), json_strings(r.walls), json_strings(r.doors),
          json_strings(r.windows));
    }
  return out + (first ? "],\n" : "\n  ],\n");
}

/// One line per room: "room 1  14.44 m2  walls a, b  doors d  windows none", after the name of
/// its level in a plan with levels ("room 1 of level 'L1'") and the name the plan gives it
/// ("room 2 (Kitchen)").
std::string text_rooms(const std::vector<LevelRooms>& levels, const Plan& plan) {
  const auto list = [](const std::vector<std::string>& ids) {
    return ids.empty() ? std::string("none") : fmt::format("{}", fmt::join(ids, ", "));
  };
  std::size_t count = 0;
  for (const LevelRooms& l : levels) count += l.rooms.size();
  std::string out =
      fmt::format("  rooms     {}{}\n", count, count == 0 ? " (no closed region of walls)" : "");
  for (const LevelRooms& l : levels) {
    const std::vector<const RoomLabel*> labels = room_labels(l.rooms, plan);
    for (std::size_t i = 0; i < l.rooms.size(); ++i) {
      const Room& r = l.rooms[i];
      out += fmt::format("    room {}{}{}  {:.2f} m2 clear  walls {}  doors {}  windows {}\n",
                         i + 1, l.level.empty() ? "" : fmt::format(" of level '{}'", l.level),
                         labels[i] ? fmt::format(" ({})", labels[i]->name) : "", r.area,
                         list(r.walls), list(r.doors), list(r.windows));
    }
  }
  return out;
}

void print_json(const std::string& file, const Plan& plan, const PlanInfo& info) {
  const Site& s = plan.site;
  const auto xyz = [](const Vec3& v) {
    return fmt::format("[{}, {}, {}]", json_number(v.x), json_number(v.y), json_number(v.z));
  };
  std::string out = "{\n";
  out += fmt::format("  \"file\": {},\n", json_string(file));
  out += fmt::format(
      "  \"site\": {{\"origin\": [{}, {}], \"cells\": [{}, {}], \"cell_size\": {}, "
      "\"size\": [{}, {}], \"max_height\": {}}},\n",
      json_number(s.origin.x), json_number(s.origin.y), s.cells[0], s.cells[1],
      json_number(s.cell_size), json_number(static_cast<double>(s.cells[0]) * s.cell_size),
      json_number(static_cast<double>(s.cells[1]) * s.cell_size), json_number(s.max_height));
  out += "  \"location\": ";
  out += s.location
             ? fmt::format("{{\"latitude\": {}, \"longitude\": {}, \"utc_offset\": {}}}",
                           json_number(s.location->latitude), json_number(s.location->longitude),
                           json_number(s.location->utc_offset))
             : "null";
  out += fmt::format(",\n  \"north\": {},\n  \"obstructions\": {},\n",
                     json_number(s.north.value_or(0.0)), plan.obstructions.size());
  out += fmt::format("  \"walls\": {},\n  \"openings\": {},\n  \"doors\": {},\n", plan.walls.size(),
                     plan.openings.size(), info.doors);
  out += fmt::format("  \"windows\": {},\n  \"lights\": {},\n  \"cameras\": {},\n", info.windows,
                     plan.lights.size(), plan.cameras.size());
  out += fmt::format("  \"total_wall_length\": {},\n  \"max_wall_height\": {},\n",
                     json_number(info.total_wall_length), json_number(info.max_wall_height));
  out += json_rooms(info.rooms);
  out += "  \"bounds\": ";
  out += info.bounds ? fmt::format("{{\"min\": {}, \"max\": {}}}", xyz(info.bounds->min),
                                   xyz(info.bounds->max))
                     : "null";
  out += "\n}\n";
  std::fputs(out.c_str(), stdout);
}

void print_text(const std::string& file, const Plan& plan, const PlanInfo& info) {
  const Site& s = plan.site;
  std::string out = file + '\n';
  out += fmt::format(
      "  site      {} x {} cells of {} m = {} m x {} m from ({}, {}), max height {} m\n",
      s.cells[0], s.cells[1], metres(s.cell_size),
      metres(static_cast<double>(s.cells[0]) * s.cell_size),
      metres(static_cast<double>(s.cells[1]) * s.cell_size), metres(s.origin.x), metres(s.origin.y),
      metres(s.max_height));
  if (s.location)
    out += fmt::format(
        "  location  {}° {}, {}° {}, UTC{:+g}; true north {}° counter-clockwise from +y\n",
        std::fabs(s.location->latitude), s.location->latitude < 0 ? "S" : "N",
        std::fabs(s.location->longitude), s.location->longitude < 0 ? "W" : "E",
        s.location->utc_offset, s.north.value_or(0.0));
  if (!plan.obstructions.empty())
    out += fmt::format("  obstructions {} (neighbours: they cast shadows)\n",
                       plan.obstructions.size());
  out += fmt::format("  walls     {}, {} m long in all, up to {} m high\n", plan.walls.size(),
                     metres(info.total_wall_length), metres(info.max_wall_height));
  out += fmt::format("  openings  {}: {} door{}, {} window{}\n", plan.openings.size(), info.doors,
                     info.doors == 1 ? "" : "s", info.windows, info.windows == 1 ? "" : "s");
  out += fmt::format("  lights    {}{}\n", plan.lights.size(),
                     plan.lights.empty() ? " (the default sun is used)" : "");
  out += fmt::format("  cameras   {}{}\n", plan.cameras.size(),
                     plan.cameras.empty() ? " (a camera framing the plan is used)" : "");
  if (info.bounds) {
    const Box3& b = *info.bounds;
    out += fmt::format("  bounds    x {} .. {} m, y {} .. {} m, z {} .. {} m\n", metres(b.min.x),
                       metres(b.max.x), metres(b.min.y), metres(b.max.y), metres(b.min.z),
                       metres(b.max.z));
  } else {
    out += "  bounds    none (no walls)\n";
  }
  out += text_rooms(info.rooms, plan);
  std::fputs(out.c_str(), stdout);
}

int run_info(const InfoOptions& options) {
  const Result<LoadedPlan> loaded = load_plan("info", options.plan);
  if (!loaded) return exit_status_of(loaded.code());
  const PlanInfo info = measure(loaded->plan);
  if (options.format == "json") {
    print_json(options.plan, loaded->plan, info);
  } else {
    print_text(options.plan, loaded->plan, info);
  }
  return std::fflush(stdout) == 0 ? kExitOk : kExitCannotRun;
}

}  // namespace

void add_info_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* app = root.add_subcommand(
      "info",
      "Describe a plan: the site (cells, size in metres, max height), how many walls, openings\n"
      "(doors and windows), lights and cameras it has, the total length of its walls (along\n"
      "their centre lines), the tallest wall, the bounds of the walls (their footprints,\n"
      "mitred corners included, from base to top), and its rooms (closed regions of the walls'\n"
      "centre lines; level by level in a plan with levels) with their clear floor areas inside\n"
      "the walls. Problems found while\n"
      "reading are printed to stderr; warnings (such as unknown fields) do not stop it. It does\n"
      "not validate the geometry (see `roomcad validate`).");
  app->add_option("PLAN", options->plan, "the plan file (JSON)")->required()->type_name("FILE");
  add_format_option(*app, options->format);
  app->footer(
      "Exit status: 0 described; 1 PLAN has errors (printed to stderr); 2 could not run (bad\n"
      "arguments, PLAN unreadable).\n"
      "Examples:\n"
      "  roomcad info examples/house.json\n"
      "  roomcad info --format json examples/flat.json");
  commands.push_back({app, [options] { return run_info(*options); }});
}

}  // namespace roomcad::cli
