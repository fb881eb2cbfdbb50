// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_rooms.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "geometry/polygon_predicates.h"
#include "import/detail/sh3d_cut_out.h"
#include "import/detail/sh3d_walls.h"
#include "plan/signed_area.h"

namespace roomcad::sh3d {
namespace {

struct Band {
  double lo = 0.0;  ///< absolute z, metres
  double hi = 0.0;
};

struct Bounds {
  Point2 min{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Point2 max{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
};

Bounds bounds_of(const Polygon& p) {
  Bounds b;
  for (const Point2& c : p) {
    b.min = {std::min(b.min.x, c.x), std::min(b.min.y, c.y)};
    b.max = {std::max(b.max.x, c.x), std::max(b.max.y, c.y)};
  }
  return b;
}

bool boxes_meet(const Bounds& a, const Bounds& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

/// The room's outline: repeated points dropped, counter-clockwise; empty if it has no area.
Polygon outline_of(const RoomRecord& room) {
  Polygon p;
  for (const Point2& c : room.points)
    if (p.empty() || !(p.back() == c)) p.push_back(c);
  while (p.size() > 1 && p.front() == p.back()) p.pop_back();
  const double area = signed_area(p);
  if (p.size() < 3 || !(std::abs(area) > 0)) return {};
  if (area < 0) std::ranges::reverse(p);
  return p;
}

/// A floor or ceiling slab that will be made, with its absolute band for the ceiling test.
struct Planned {
  Slab slab;
  Band band;
  Bounds box;
};

/// The middle of the widest run inside `outline` along the line halfway up its box.
/// @pre outline has area.
Point2 point_inside(const Polygon& outline) {
  const Bounds box = bounds_of(outline);
  const double y = box.min.y + (box.max.y - box.min.y) / 2.0;
  std::vector<double> xs;  // where the edges cross the line, each edge half-open at its top
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Point2 a = outline[i], b = outline[(i + 1) % outline.size()];
    if ((a.y > y) != (b.y > y)) xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
  }
  std::ranges::sort(xs);
  Point2 best{(box.min.x + box.max.x) / 2.0, y};
  double widest = -1.0;
  for (std::size_t k = 0; k + 1 < xs.size(); k += 2)
    if (xs[k + 1] - xs[k] > widest) {
      widest = xs[k + 1] - xs[k];
      best = {xs[k] + widest / 2.0, y};
    }
  return best;
}

}  // namespace

std::vector<RoomLabel> make_room_labels(const std::vector<RoomRecord>& rooms,
                                        const std::vector<PlacedLevel>& levels) {
  std::vector<RoomLabel> labels;
  for (std::size_t k = 0; k < rooms.size(); ++k) {
    const RoomRecord& room = rooms[k];
    const Polygon outline = outline_of(room);
    if (room.name.find_first_not_of(" \t\n") == std::string::npos || outline.empty()) continue;
    const PlacedLevel* level = find_placed(levels, room.level);
    RoomLabel label;
    label.id = (room.id.empty() ? fmt::format("room{}", k + 1) : room.id) + "-name";
    label.level = level ? level->level.id : std::string();
    label.at = point_inside(outline);
    label.name = room.name;
    labels.push_back(std::move(label));
  }
  return labels;
}

std::vector<Slab> make_slabs(const Home& home, const std::vector<RoomRecord>& rooms,
                             const std::vector<PlacedLevel>& levels, double base_z,
                             bool ceilings_too, Report& warnings) {
  std::vector<Planned> floors;
  std::vector<Planned> ceilings;
  for (std::size_t k = 0; k < rooms.size(); ++k) {
    const RoomRecord& room = rooms[k];
    const std::string id = room.id.empty() ? fmt::format("room{}", k + 1) : room.id;
    const Polygon outline = outline_of(room);
    if (outline.empty() || !is_simple_polygon(outline)) {
      warnings.add(import_warning(
          Code::import_skipped_element, id,
          outline.empty()
              ? fmt::format("room '{}' ({}) encloses no area; it has no floor or ceiling slab", id,
                            room.name)
              : fmt::format("the outline of room '{}' ({}) crosses or runs back along itself "
                            "(as a slit drawn around a stair well does), which a slab's outline "
                            "may not; it has no floor or ceiling slab (redraw the well as a "
                            "hole: roomcad set ... holes=...)",
                            id, room.name)));
      continue;
    }
    const PlacedLevel* level = find_placed(levels, room.level);
    const double ft = z_of(level ? level->floor_thickness_cm : kDefaultFloorThicknessCm);
    const double elevation = level ? level->level.elevation : base_z;
    const double height = level ? level->level.height : z_of(home.wall_height_cm.value_or(250.0));
    Slab slab;
    slab.level = level ? level->level.id : std::string();
    slab.outline = outline;
    slab.thickness = ft;
    if (room.floor_visible && level && level->floor_offset_cm > 0 && ft > 0) {
      Slab floor = slab;
      floor.id = id;
      floor.top = 0.0;
      if (room.floor_color) floor.color = *room.floor_color;
      floors.push_back({floor, {elevation - ft, elevation}, bounds_of(outline)});
    }
    if (ceilings_too && room.ceiling_visible && ft > 0) {
      Slab ceiling = slab;
      ceiling.id = id + "-ceiling";
      ceiling.top = level ? height + ft : elevation + height + ft;
      if (room.ceiling_color) ceiling.color = *room.ceiling_color;
      ceilings.push_back(
          {ceiling, {elevation + height, elevation + height + ft}, bounds_of(outline)});
    }
  }
  std::vector<Slab> slabs;
  for (const Planned& f : floors) slabs.push_back(f.slab);
  for (const Planned& c : ceilings) {
    const bool covered = std::ranges::any_of(floors, [&](const Planned& f) {
      return f.band.lo < c.band.hi && c.band.lo < f.band.hi && boxes_meet(f.box, c.box);
    });
    if (!covered) slabs.push_back(c.slab);
  }
  return slabs;
}

}  // namespace roomcad::sh3d
