// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/plan_levels.h"

#include <algorithm>
#include <set>
#include <string>

namespace roomcad {

const Level* find_level(const Plan& plan, std::string_view id) {
  if (id.empty()) return nullptr;
  const auto it = std::find_if(plan.levels.begin(), plan.levels.end(), [&](const Level& l) { return l.id == id; });
  return it == plan.levels.end() ? nullptr : &*it;
}

double level_elevation(const Plan& plan, std::string_view id) {
  const Level* level = find_level(plan, id);
  return level == nullptr ? 0.0 : level->elevation;
}

double wall_base_z(const Plan& plan, const Wall& wall) { return level_elevation(plan, wall.level) + wall.base; }

double slab_top_z(const Plan& plan, const Slab& slab) { return level_elevation(plan, slab.level) + slab.top; }

Plan with_levels_resolved(const Plan& plan) {
  Plan out = plan;
  for (Wall& w : out.walls) w.base = wall_base_z(plan, w), w.level.clear();
  for (Slab& s : out.slabs) s.top = slab_top_z(plan, s), s.level.clear();
  return out;
}

Plan plan_of_level(const Plan& plan, std::string_view id) {
  Plan out = plan;
  std::erase_if(out.walls, [&](const Wall& w) { return w.level != id; });
  std::erase_if(out.slabs, [&](const Slab& s) { return s.level != id; });
  std::set<std::string, std::less<>> kept;
  for (const Wall& w : out.walls) kept.insert(w.id);
  std::erase_if(out.openings, [&](const Opening& o) { return !kept.contains(o.wall); });
  return out;
}

}  // namespace roomcad
