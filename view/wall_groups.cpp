// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/wall_groups.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string_view>
#include <unordered_set>

#include "geometry/broad_phase.h"
#include "geometry/joins.h"

namespace roomcad {
namespace {

/// True for a straight wall of positive finite length and thickness: one whose footprint
/// (wall_footprint) is where its solid is.
bool has_plain_footprint(const Wall& w) {
  const bool finite = std::isfinite(w.from.x) && std::isfinite(w.from.y) && std::isfinite(w.to.x) &&
                      std::isfinite(w.to.y);
  const bool has_length = w.from.x != w.to.x || w.from.y != w.to.y;
  return !w.arc_extent && finite && has_length && std::isfinite(w.thickness) && w.thickness > 0;
}

/// True when the groups can be told from footprints and joins alone (see the header).
bool can_split(const Plan& plan) {
  if (!plan.slabs.empty()) return false;
  std::unordered_set<std::string_view> ids;
  for (const Wall& w : plan.walls)
    if (!has_plain_footprint(w) || !ids.insert(w.id).second) return false;
  return std::all_of(plan.openings.begin(), plan.openings.end(),
                     [&](const Opening& o) { return ids.count(o.wall) > 0; });
}

Box2 grown_box(const std::array<Point2, 4>& corners, std::size_t index) {
  Box2 box{corners[0].x, corners[0].y, corners[0].x, corners[0].y, index};
  for (const Point2& p : corners) {
    box.min_x = std::min(box.min_x, p.x), box.max_x = std::max(box.max_x, p.x);
    box.min_y = std::min(box.min_y, p.y), box.max_y = std::max(box.max_y, p.y);
  }
  box.min_x -= kGroupMargin, box.min_y -= kGroupMargin;
  box.max_x += kGroupMargin, box.max_y += kGroupMargin;
  return box;
}

/// Union-find over 0..n-1 (path halving; sizes are small, no ranks needed for speed).
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace

std::vector<std::vector<std::size_t>> find_wall_groups(const Plan& plan) {
  const std::size_t n = plan.walls.size();
  if (n == 0) return {};
  if (!can_split(plan)) {
    std::vector<std::size_t> all(n);
    std::iota(all.begin(), all.end(), std::size_t{0});
    return {all};
  }
  const Joins joins = find_joins(plan);
  std::vector<Box2> boxes;
  boxes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) boxes.push_back(grown_box(wall_footprint(plan, joins, i), i));
  DisjointSets sets(n);
  for (const Join& j : joins.pairs) sets.unite(j.a, j.b);
  for (const auto& [a, b] : find_meeting_boxes(boxes)) sets.unite(a, b);
  std::vector<std::vector<std::size_t>> groups;
  std::vector<std::size_t> group_of_root(n, n);
  for (std::size_t i = 0; i < n; ++i) {  // ascending: groups come out ordered by first wall
    std::size_t& group = group_of_root[sets.find(i)];
    if (group == n) group = groups.size(), groups.emplace_back();
    groups[group].push_back(i);
  }
  return groups;
}

}  // namespace roomcad
