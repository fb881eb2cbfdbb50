// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/detail/resolved_plan.h"

#include <algorithm>
#include <cmath>

#include "plan/plan_chords.h"
#include "plan/plan_levels.h"

namespace roomcad::detail {

ResolvedPlan resolve_plan(const Plan& plan, const Usable& usable) {
  // A level that is missing (an unknown_reference) or has a bad elevation (an invalid_value)
  // leaves its objects unplaced: nothing more is said about them.
  const auto placed_on = [&plan](const std::string& level) {
    return level.empty() ||
           (find_level(plan, level) && std::isfinite(level_elevation(plan, level)));
  };
  const Plan absolute = with_absolute_heights(plan);
  ChordPlan chords = with_arcs_as_chords(absolute);
  ResolvedPlan r;
  r.usable.site = usable.site;
  std::vector<bool> placed(plan.walls.size());
  std::vector<std::size_t> index_of(plan.walls.size());  // an input wall's first wall in r
  for (std::size_t w = plan.walls.size(); w-- > 0;)
    placed[w] = usable.walls[w] && placed_on(plan.walls[w].level) &&
                std::isfinite(absolute.walls[w].base) &&
                std::isfinite(absolute.walls[w].base + absolute.walls[w].height);
  for (std::size_t j = chords.source_wall.size(); j-- > 0;) index_of[chords.source_wall[j]] = j;
  for (const std::size_t w : chords.source_wall) r.usable.walls.push_back(placed[w]);
  for (std::size_t j = 0; j < chords.plan.openings.size(); ++j) {
    const std::optional<std::size_t> host = usable.host[chords.source_opening[j]];
    if (!host || !placed[*host]) r.usable.host.push_back(std::nullopt);
    else r.usable.host.push_back(chords.chord[j] != kNoChord ? chords.chord[j] : index_of[*host]);
  }
  r.usable.slabs = usable.slabs;
  r.usable.obstructions = usable.obstructions;
  for (std::size_t i = 0; i < absolute.slabs.size(); ++i)
    r.usable.slabs[i] =
        r.usable.slabs[i] && placed_on(plan.slabs[i].level) && std::isfinite(absolute.slabs[i].top);
  r.plan = std::move(chords.plan);
  r.source_wall = std::move(chords.source_wall);
  return r;
}

}  // namespace roomcad::detail
