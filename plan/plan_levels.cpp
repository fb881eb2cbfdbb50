// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan_levels.h"

#include <algorithm>
#include <string>
#include <unordered_set>

#include "core/error.h"

namespace roomcad {

const Level* find_level(const Plan& plan, std::string_view id) {
  if (id.empty()) return nullptr;
  const auto it = std::find_if(plan.levels.begin(), plan.levels.end(),
                               [id](const Level& l) { return l.id == id; });
  return it == plan.levels.end() ? nullptr : &*it;
}

double level_elevation(const Plan& plan, std::string_view id) {
  const Level* level = find_level(plan, id);
  return level ? level->elevation : 0.0;
}

double base_z(const Plan& plan, const Wall& wall) {
  return level_elevation(plan, wall.level) + wall.base;
}

double top_z(const Plan& plan, const Slab& slab) {
  return level_elevation(plan, slab.level) + slab.top;
}

Plan with_absolute_heights(Plan plan) {
  for (Wall& w : plan.walls) {
    w.base = base_z(plan, w);
    w.level.clear();
  }
  for (Slab& s : plan.slabs) {
    s.top = top_z(plan, s);
    s.level.clear();
  }
  return plan;
}

Plan plan_of_level(const Plan& plan, std::string_view level) {
  if (find_level(plan, level) == nullptr)
    throw PreconditionError("the plan has no level '" + std::string(level) + "'");
  Plan part = plan;
  std::erase_if(part.walls, [level](const Wall& w) { return w.level != level; });
  std::erase_if(part.slabs, [level](const Slab& s) { return s.level != level; });
  std::unordered_set<std::string> walls;
  for (const Wall& w : part.walls) walls.insert(w.id);
  std::erase_if(part.openings, [&walls](const Opening& o) { return !walls.contains(o.wall); });
  return part;
}

Result<Plan> select_level(const Plan& plan, std::string_view level) {
  if (level.empty()) return plan;
  if (find_level(plan, level) != nullptr) return plan_of_level(plan, level);
  std::string known;
  for (const Level& l : plan.levels) known += (known.empty() ? "'" : ", '") + l.id + "'";
  return Result<Plan>::failure(
      Code::usage_error,
      "--level '" + std::string(level) +
          "': the plan has no such level (its levels: " + (known.empty() ? "none" : known) + ")");
}

}  // namespace roomcad
