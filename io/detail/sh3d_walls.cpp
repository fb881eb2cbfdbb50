#include "io/detail/sh3d_walls.h"

#include "io/detail/sh3d_junctions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <fmt/format.h>

namespace roomcad::sh3d {
namespace {

constexpr int kMaxChords = 256;  // bounds the output for a tiny tolerance on a huge arc

double distance(Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

/// The wall's height: its own, else the home's default, else its level's, else 2.5 m (Sweet
/// Home 3D's default). A sloped top becomes flat at its higher end, with a warning.
double flat_height(const Home& home, const WallRecord& w, Report& warnings) {
  double height = 2.5;
  if (w.height) height = *w.height;
  else if (home.wall_height) height = *home.wall_height;
  else if (const auto l = std::ranges::find(home.levels, w.level, &Level::id);
           l != home.levels.end() && l->height > 0)
    height = l->height;
  if (w.height_at_end && *w.height_at_end != height) {
    const double top = std::max(height, *w.height_at_end);
    warnings.add(import_warning(
        "import_sloped_wall", w.id,
        fmt::format("wall '{}' has a sloped top from {:.3f} m to {:.3f} m; the plan format has "
                    "one height per wall, so it is imported flat at {:.3f} m",
                    w.id, height, *w.height_at_end, top)));
    height = top;
  }
  return height;
}

Wall make_wall(const WallRecord& w, std::string id, Point2 from, Point2 to, double height,
               const LevelBase& base) {
  Wall wall;
  wall.id = std::move(id);
  wall.from = from;
  wall.to = to;
  wall.thickness = w.thickness;
  wall.height = height + base.floor_offset;
  wall.base = base.base;
  if (w.color) wall.color = *w.color;
  return wall;
}

}  // namespace

Diagnostic import_warning(std::string code, const std::string& id, std::string message) {
  Diagnostic d;
  d.severity = Severity::warning;
  d.code = std::move(code);
  d.objects = {id};
  d.message = std::move(message);
  return d;
}

LevelBase level_base(const Home& home, const std::string& level_id) {
  const auto level = std::ranges::find(home.levels, level_id, &Level::id);
  if (level == home.levels.end()) return {};
  const double lowest = std::ranges::min(home.levels, {}, &Level::elevation).elevation;
  const double offset = level->elevation == lowest ? 0.0 : level->floor_thickness;
  return {.base = level->elevation - offset, .floor_offset = offset};
}

std::vector<Point2> split_arc(Point2 a, Point2 b, double extent, double tolerance) {
  const double chord = distance(a, b);
  const double sweep = std::min(std::abs(extent), 2 * std::numbers::pi);
  const double radius = chord / (2 * std::sin(sweep / 2));
  const double side = extent > 0 ? 1.0 : -1.0;
  // Centre: from the chord's midpoint, away from the bulge (toward it for arcs over 180°).
  const Point2 left{-(b.y - a.y) / chord, (b.x - a.x) / chord};
  const double to_centre = -side * radius * std::cos(sweep / 2);
  const Point2 centre{(a.x + b.x) / 2 + left.x * to_centre, (a.y + b.y) / 2 + left.y * to_centre};
  // A chord spanning angle phi strays radius * (1 - cos(phi / 2)) from the arc.
  const double max_step = 2 * std::acos(std::max(-1.0, 1 - tolerance / radius));
  const int chords = std::clamp(static_cast<int>(std::ceil(sweep / max_step)), 1, kMaxChords);
  const double start = std::atan2(a.y - centre.y, a.x - centre.x);
  std::vector<Point2> points{a};
  for (int k = 1; k < chords; ++k) {
    const double angle = start - side * sweep * k / chords;  // a left bulge turns clockwise
    points.push_back({centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)});
  }
  points.push_back(b);
  return points;
}

std::vector<PlacedWall> convert_walls(const Home& home, std::vector<WallRecord> walls,
                                      const WallOptions& options, Report& warnings) {
  snap_close_ends(walls, options.snap_distance);
  join_t_ends(walls, options.snap_distance, warnings);
  std::vector<PlacedWall> placed;
  for (const WallRecord& w : walls) {
    const LevelBase base = level_base(home, w.level);
    const double height = flat_height(home, w, warnings);
    if (!w.arc_extent || *w.arc_extent == 0 || w.start == w.end) {
      placed.push_back({make_wall(w, w.id, w.start, w.end, height, base), w.level,
                        base.floor_offset});
      continue;
    }
    const std::vector<Point2> points =
        split_arc(w.start, w.end, *w.arc_extent, options.chord_tolerance);
    for (std::size_t k = 1; k < points.size(); ++k)
      placed.push_back({make_wall(w, fmt::format("{}-arc{}", w.id, k), points[k - 1], points[k],
                                  height, base),
                        w.level, base.floor_offset});
    warnings.add(import_warning(
        "import_curved_wall", w.id,
        fmt::format("curved wall '{}' ({:.1f} degrees of arc) is imported as {} straight walls "
                    "'{}-arc1'..'{}-arc{}' within {} m of the arc",
                    w.id, std::abs(*w.arc_extent) * 180 / std::numbers::pi, points.size() - 1,
                    w.id, w.id, points.size() - 1, options.chord_tolerance)));
  }
  return placed;
}

}  // namespace roomcad::sh3d
