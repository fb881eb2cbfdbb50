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
void link_walls(const std::vector<WallFrame>& frames, const Joins& joins, const std::vector<int>& hub_of,
                std::vector<char>& general, DisjointSets& sets) {
  auto explained = [&](std::size_t a, std::size_t b) {
    // A unite join is explained when both walls are arms of one hub (one end of each).
    for (int ha : {hub_of[2 * a], hub_of[2 * a + 1]})
      if (ha >= 0 && (ha == hub_of[2 * b] || ha == hub_of[2 * b + 1])) return true;
    return false;
  };
  for (const Join& j : joins.pairs) {
    sets.unite(j.a, j.b);
    const bool plain = j.kind == JoinKind::mitre ? is_same_height(frames[j.a], frames[j.b])
                                                 : explained(j.a, j.b);
    if (!plain) general[j.a] = general[j.b] = 1;
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

// hub_of[2 * wall + end]: the hub that wall end is an arm of, or -1.
std::vector<int> index_hubs(const std::vector<Hub>& hubs, std::size_t walls) {
  std::vector<int> hub_of(2 * walls, -1);
  for (std::size_t h = 0; h < hubs.size(); ++h)
    for (const auto& [wall, end] : hubs[h].arms) hub_of[2 * wall + std::size_t(end)] = int(h);
  return hub_of;
}

// root_general[root]: the component of that root holds a wall that needs the general path.
std::vector<char> find_general_components(const std::vector<char>& general, DisjointSets& sets) {
  std::vector<char> root_general(general.size(), 0);
  for (std::size_t i = 0; i < general.size(); ++i)
    if (general[i]) root_general[sets.find(i)] = 1;
  return root_general;
}

std::vector<WorkItem> group_walls(const std::vector<char>& root_general, DisjointSets& sets) {
  const std::size_t n = root_general.size();
  std::vector<WorkItem> items;
  std::vector<std::size_t> item_of_root(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t root = sets.find(i);
    if (!root_general[root]) {
      items.push_back({WorkItem::Kind::fast_wall, {i}, 0});
      continue;
    }
    if (item_of_root[root] == n) {
      item_of_root[root] = items.size();
      items.push_back({WorkItem::Kind::cluster, {}, 0});
    }
    items[item_of_root[root]].walls.push_back(i);
  }
  return items;
}

}  // namespace

Work plan_work(const std::vector<WallFrame>& frames, const Joins& joins, BooleanPath path) {
  const std::size_t n = frames.size();
  Work work;
  work.fast_frames = frames;
  if (path != BooleanPath::cgal) work.hubs = find_hubs(frames, joins);
  for (const Hub& hub : work.hubs) attach_hub(hub, work.fast_frames);
  const std::vector<int> hub_of = index_hubs(work.hubs, n);
  std::vector<char> general(n, path == BooleanPath::cgal ? 1 : 0);
  DisjointSets sets(n);
  link_walls(frames, joins, hub_of, general, sets);
  for (std::size_t i = 0; i < n; ++i)
    if (!has_holes_clear_of_mitres(work.fast_frames[i])) general[i] = 1;
  const std::vector<char> root_general = find_general_components(general, sets);
  work.items = group_walls(root_general, sets);
  // A hub among fast walls adds its top and bottom; a cluster's hubs are CGAL's business.
  for (std::size_t h = 0; h < work.hubs.size(); ++h)
    if (!root_general[sets.find(work.hubs[h].arms.front().first)])
      work.items.push_back({WorkItem::Kind::hub, {}, h});
  return work;
}

}  // namespace roomcad::detail
