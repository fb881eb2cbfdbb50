// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_levels.h"

#include <algorithm>
#include <map>

#include "import/detail/sh3d_walls.h"

namespace roomcad::sh3d {

std::vector<PlacedLevel> place_levels(const Home& home, const std::vector<sh3d::Level>& levels,
                                      double z_shift_cm,
                                      const std::set<std::string, std::less<>>& taken) {
  std::map<std::string, int, std::less<>> names;
  for (const sh3d::Level& l : home.levels) ++names[l.name];
  std::vector<PlacedLevel> placed;
  for (const sh3d::Level& l : levels) {
    const bool name_usable = !l.name.empty() && names[l.name] == 1 && !taken.contains(l.name);
    const LevelBase base = level_base(home, l.id);
    double height_cm = l.height_cm;
    if (height_cm <= 0) height_cm = home.wall_height_cm.value_or(250.0);
    if (height_cm <= 0) height_cm = 250.0;
    roomcad::Level level;
    level.id = name_usable ? l.name : l.id;
    level.elevation = z_of(l.elevation_cm + z_shift_cm);
    level.height = z_of(height_cm);
    placed.push_back({l.id, std::move(level), base.floor_offset_cm, l.floor_thickness_cm});
  }
  return placed;
}

const PlacedLevel* find_placed(const std::vector<PlacedLevel>& levels,
                               const std::string& source_id) {
  if (source_id.empty()) return nullptr;
  const auto it = std::ranges::find(levels, source_id, &PlacedLevel::source_id);
  return it == levels.end() ? nullptr : &*it;
}

}  // namespace roomcad::sh3d
