#include "modeling/detail/clusters.h"

#include <algorithm>
#include <numeric>

#include "modeling/broad_phase.h"
#include "modeling/detail/fast_wall.h"

namespace roomcad::detail {
namespace {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

Box2 box_of(const WallFrame& f) {
  Box2 b{f.footprint[0].x, f.footprint[0].y, f.footprint[0].x, f.footprint[0].y, f.wall};
  for (const Point2& p : f.footprint) {
    b.min_x = std::min(b.min_x, p.x), b.max_x = std::max(b.max_x, p.x);
    b.min_y = std::min(b.min_y, p.y), b.max_y = std::max(b.max_y, p.y);
  }
  return b;
}

bool is_same_height(const WallFrame& a, const WallFrame& b) { return a.base == b.base && a.top == b.top; }

// Marks walls that need the general path and links the walls that must be built together.
void link_walls(const std::vector<WallFrame>& frames, const Joins& joins,
                std::vector<char>& general, DisjointSets& sets) {
  for (const Join& j : joins.pairs) {
    sets.unite(j.a, j.b);
    if (j.kind == JoinKind::unite || !is_same_height(frames[j.a], frames[j.b]))
      general[j.a] = general[j.b] = 1;
  }
  std::vector<Box2> boxes;
  boxes.reserve(frames.size());
  for (const WallFrame& f : frames) boxes.push_back(box_of(f));
  for (const auto& [a, b] : find_meeting_boxes(boxes)) {
    if (joins.are_joined(a, b)) continue;
    if (frames[a].top < frames[b].base || frames[b].top < frames[a].base) continue;
    sets.unite(a, b);
    general[a] = general[b] = 1;
  }
}

}  // namespace

std::vector<WorkItem> plan_work(const std::vector<WallFrame>& frames, const Joins& joins,
                                BooleanPath path) {
  const std::size_t n = frames.size();
  std::vector<char> general(n, path == BooleanPath::cgal ? 1 : 0);
  DisjointSets sets(n);
  link_walls(frames, joins, general, sets);
  for (std::size_t i = 0; i < n; ++i)
    if (!has_holes_clear_of_mitres(frames[i])) general[i] = 1;
  std::vector<char> root_general(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (general[i]) root_general[sets.find(i)] = 1;
  std::vector<WorkItem> items;
  std::vector<std::size_t> item_of_root(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t root = sets.find(i);
    if (!root_general[root]) {
      items.push_back({false, {i}});
      continue;
    }
    if (item_of_root[root] == n) {
      item_of_root[root] = items.size();
      items.push_back({true, {}});
    }
    items[item_of_root[root]].walls.push_back(i);
  }
  return items;
}

}  // namespace roomcad::detail
