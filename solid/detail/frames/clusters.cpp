// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/frames/clusters.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <tuple>
#include <utility>

#include "geometry/broad_phase.h"
#include "solid/detail/fast_path/fast_wall.h"

namespace roomcad::detail {
namespace {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
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

// Whether two footprints are certainly apart: some edge normal of either separates them by
// more than a small margin (so shapes that touch, or nearly, count as meeting). O(1).
bool are_apart(const WallFrame& a, const WallFrame& b) {
  double scale = 1.0;
  for (const WallFrame* f : {&a, &b})
    for (const Point2& p : f->footprint) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  const double margin = 1e-9 * scale;
  for (const WallFrame* f : {&a, &b})
    for (std::size_t k = 0; k < 4; ++k) {
      const Point2 p = f->footprint[k], q = f->footprint[(k + 1) % 4];
      const double nx = q.y - p.y, ny = p.x - q.x, len = std::hypot(nx, ny);
      if (len == 0.0) continue;
      auto range = [&](const WallFrame& g) {
        double lo = INFINITY, hi = -INFINITY;
        for (const Point2& r : g.footprint) {
          const double d = ((r.x - p.x) * nx + (r.y - p.y) * ny) / len;
          lo = std::min(lo, d), hi = std::max(hi, d);
        }
        return std::pair{lo, hi};
      };
      const auto [alo, ahi] = range(a);
      const auto [blo, bhi] = range(b);
      if (ahi < blo - margin || bhi < alo - margin) return true;
    }
  return false;
}

bool is_same_height(const WallFrame& a, const WallFrame& b) {
  return a.base == b.base && a.top == b.top && !is_sloped(a) && !is_sloped(b);
}

// The two corners of a footprint's end (0: from, 1: to), in ascending order.
std::pair<Point2, Point2> end_corners(const WallFrame& f, std::size_t end) {
  const Point2 p = f.footprint[end == 0 ? 0 : 1], q = f.footprint[end == 0 ? 3 : 2];
  return std::minmax(p, q,
                     [](Point2 u, Point2 v) { return std::tie(u.x, u.y) < std::tie(v.x, v.y); });
}

// Whether every end of `a` mitred to `b` has the very end face of an end of `b` mitred to `a`.
// The fast path leaves both mitred ends open, so they must close each other: not so for a
// straight run from one thickness to another (square ends of two widths) or for ends that
// are only within tolerance of each other in a straight run.
bool mitre_ends_coincide(const std::vector<WallFrame>& frames, const Joins& joins, std::size_t a,
                         std::size_t b) {
  for (std::size_t e = 0; e < 2; ++e) {
    if (joins.mitre[a][e] != b) continue;
    bool matched = false;
    for (std::size_t f = 0; f < 2; ++f)
      matched = matched ||
                (joins.mitre[b][f] == a && end_corners(frames[a], e) == end_corners(frames[b], f));
    if (!matched) return false;
  }
  return true;
}

using PairSet = std::set<std::pair<std::size_t, std::size_t>>;

// Marks walls that need the general path and links the walls that must be built together.
// A unite join is plain when a hub or a tee builds it (`explained`, pairs a < b).
void link_walls(const std::vector<WallFrame>& frames, const Joins& joins, const PairSet& explained,
                std::vector<char>& general, DisjointSets& sets) {
  for (const Join& j : joins.pairs) {
    sets.unite(j.a, j.b);
    const bool plain = j.kind == JoinKind::mitre ? is_same_height(frames[j.a], frames[j.b]) &&
                                                       mitre_ends_coincide(frames, joins, j.a, j.b)
                                                 : explained.count({j.a, j.b}) > 0;
    if (!plain) general[j.a] = general[j.b] = 1;
  }
  std::vector<SpaceBox> boxes;
  boxes.reserve(frames.size());
  for (const WallFrame& f : frames) boxes.push_back(footprint_space_box(f));
  for (const auto& [a, b] : find_meeting_boxes(boxes)) {
    if (joins.are_joined(a, b)) continue;
    if (frames[a].top_max < frames[b].base || frames[b].top_max < frames[a].base) continue;
    if (are_apart(frames[a], frames[b])) continue;
    sets.unite(a, b);
    general[a] = general[b] = 1;
  }
}

// The pairs of walls whose unite join a hub (any two of its arms) or a tee builds.
PairSet explained_pairs(const std::vector<Hub>& hubs, const std::vector<Tee>& tees) {
  PairSet pairs;
  auto add = [&](std::size_t a, std::size_t b) { pairs.emplace(std::min(a, b), std::max(a, b)); };
  for (const Hub& h : hubs)
    for (std::size_t i = 0; i < h.arms.size(); ++i)
      for (std::size_t j = i + 1; j < h.arms.size(); ++j) add(h.arms[i].first, h.arms[j].first);
  for (const Tee& t : tees) add(t.stem, t.through);
  return pairs;
}

// root_general[root]: the component of that root holds a wall that needs the general path.
std::vector<char> find_general_components(const std::vector<char>& general, DisjointSets& sets) {
  std::vector<char> root_general(general.size(), 0);
  for (std::size_t i = 0; i < general.size(); ++i)
    if (general[i]) root_general[sets.find(i)] = 1;
  return root_general;
}

// Slab s is element n + s of the sets (n walls): it meets the walls and slabs whose boxes
// meet its box, heights included (touching counts).
void link_slabs(const std::vector<WallFrame>& frames, const std::vector<SlabFrame>& slabs,
                DisjointSets& sets) {
  const std::size_t n = frames.size();
  std::vector<SpaceBox> walls, boxes;
  for (const WallFrame& f : frames) walls.push_back(footprint_space_box(f));
  for (std::size_t s = 0; s < slabs.size(); ++s)
    boxes.push_back(space_box({slabs[s].min_x, slabs[s].min_y, slabs[s].max_x, slabs[s].max_y, s},
                              slabs[s].bottom, slabs[s].top));
  for (const auto& [w, s] : find_meeting_boxes(walls, boxes))
    if (!(frames[w].top_max < slabs[s].bottom || slabs[s].top < frames[w].base))
      sets.unite(w, n + s);
  for (const auto& [a, b] : find_meeting_boxes(boxes))
    if (!(slabs[a].top < slabs[b].bottom || slabs[b].top < slabs[a].bottom))
      sets.unite(n + a, n + b);
}

// The items of walls 0..n-1 and slabs n.. (every slab in a cluster).
std::vector<WorkItem> group_walls(std::size_t n, const std::vector<char>& root_general,
                                  DisjointSets& sets) {
  const std::size_t all = root_general.size();
  std::vector<WorkItem> items;
  std::vector<std::size_t> item_of_root(all, all);
  for (std::size_t i = 0; i < all; ++i) {
    const std::size_t root = sets.find(i);
    if (!root_general[root]) {
      items.push_back({WorkItem::Kind::fast_wall, {i}, 0, {}});
      continue;
    }
    if (item_of_root[root] == all) {
      item_of_root[root] = items.size();
      items.push_back({WorkItem::Kind::cluster, {}, 0, {}});
    }
    WorkItem& item = items[item_of_root[root]];
    (i < n ? item.walls : item.slabs).push_back(i < n ? i : i - n);
  }
  return items;
}

}  // namespace

Work plan_work(const std::vector<WallFrame>& frames, const Joins& joins, BooleanPath path,
               const std::vector<SlabFrame>& slabs) {
  const std::size_t n = frames.size();
  Work work;
  work.fast_frames = frames;
  const bool fast = path == BooleanPath::automatic || path == BooleanPath::fast_then_nef;
  if (fast) work.hubs = find_hubs(frames, joins);
  for (const Hub& hub : work.hubs) attach_hub(hub, work.fast_frames);
  if (fast) work.tees = find_tees(work.fast_frames, joins);
  attach_tees(work.tees, work.fast_frames);
  std::vector<char> general(n + slabs.size(), fast ? 0 : 1);
  std::fill(general.begin() + std::ptrdiff_t(n), general.end(), 1);
  DisjointSets sets(n + slabs.size());
  // Touching is judged on the fast-path shapes: a stem clipped at its through-wall's face no
  // longer reaches the walls on the other side (all of them are joined to that wall anyway).
  link_walls(work.fast_frames, joins, explained_pairs(work.hubs, work.tees), general, sets);
  link_slabs(frames, slabs, sets);
  for (std::size_t i = 0; i < n; ++i)
    if (!has_holes_clear_of_joins(work.fast_frames[i]) ||
        has_crossed_footprint(work.fast_frames[i]) || needs_general_path(frames[i]))
      general[i] = 1;
  const std::vector<char> root_general = find_general_components(general, sets);
  work.items = group_walls(n, root_general, sets);
  // A hub among fast walls adds its top and bottom; a cluster builds its own hubs.
  for (std::size_t h = 0; h < work.hubs.size(); ++h)
    if (!root_general[sets.find(work.hubs[h].arms.front().first)])
      work.items.push_back({WorkItem::Kind::hub, {}, h, {}});
  return work;
}

}  // namespace roomcad::detail
