// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's box intersection behind the plain interface of geometry/broad_phase.h.
#include "geometry/broad_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

#include <CGAL/box_intersection_d.h>

namespace roomcad {
namespace {

template <int Dimensions>
using CgalBox = CGAL::Box_intersection_d::Box_with_info_d<double, Dimensions, std::size_t>;

// The info is the caller's index shifted left once, its low bit telling which sequence a box
// came from, so that pairs of two sequences come out in (left, right) order whatever order
// the callback receives them in.
CgalBox<2> to_cgal(const Box2& b, std::size_t side) {
  double lo[2] = {b.min_x, b.min_y};
  double hi[2] = {b.max_x, b.max_y};
  return {lo, hi, (b.index << 1) | side};
}

CgalBox<3> to_cgal(const SpaceBox& b, std::size_t side) {
  double lo[3] = {b.plan.min_x, b.plan.min_y, b.min_z};
  double hi[3] = {b.plan.max_x, b.plan.max_y, b.max_z};
  return {lo, hi, (b.plan.index << 1) | side};
}

template <class Box>
auto to_cgal(const std::vector<Box>& boxes, std::size_t side) {
  std::vector<decltype(to_cgal(Box{}, side))> out;
  out.reserve(boxes.size());
  for (const Box& b : boxes) out.push_back(to_cgal(b, side));
  return out;
}

void sort_unique(IndexPairs& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

// A box as its bounds per axis, with the caller's index, its sequence (0 or 1) and the rank of
// its index among its sequence's.
template <int Dimensions>
struct Bounds {
  std::array<double, Dimensions> low, high;
  std::size_t index, side;
  std::uint32_t rank = 0;
};

Bounds<2> bounds_of(const Box2& b, std::size_t side) {
  return {{b.min_x, b.min_y}, {b.max_x, b.max_y}, b.index, side};
}

Bounds<3> bounds_of(const SpaceBox& b, std::size_t side) {
  return {{b.plan.min_x, b.plan.min_y, b.min_z},
          {b.plan.max_x, b.plan.max_y, b.max_z},
          b.plan.index,
          side};
}

// The axis along which the boxes overlap least: their extents' sum over the span of them all is
// smallest there, and the sweep's open boxes fewest.
template <int Dimensions>
int sweep_axis(const std::vector<Bounds<Dimensions>>& boxes) {
  int best = 0;
  double best_density = INFINITY;
  for (int a = 0; a < Dimensions; ++a) {
    double low = INFINITY, high = -INFINITY, extents = 0.0;
    for (const auto& b : boxes) {
      low = std::min(low, b.low[a]), high = std::max(high, b.high[a]);
      extents += b.high[a] - b.low[a];
    }
    const double density = extents / (high - low);
    if (density < best_density) best = a, best_density = density;  // NaN (one point) never wins
  }
  return best;
}

// Below this many boxes a sweep along one axis beats CGAL's segment tree (whose constant is
// large), even where most boxes overlap along every axis: at most n^2 / 2 tests.
constexpr std::size_t kSweepBelow = 2048;

// The pairs of ranks (first, second) as pairs of the indices of those ranks, sorted, each once:
// counted into a bucket per first rank, each bucket sorted (a sort of all the pairs took longer
// than the sweep finding them). O(n + k log(k / n)) for n ranks.
IndexPairs sorted_index_pairs(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& ranked,
                              const std::array<std::vector<std::size_t>, 2>& index_of_rank) {
  std::vector<std::uint32_t> start(index_of_rank[0].size() + 1, 0);
  for (const auto& p : ranked) ++start[p.first + 1];
  for (std::size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
  std::vector<std::uint32_t> seconds(ranked.size()), fill(start.begin(), start.end() - 1);
  for (const auto& p : ranked) seconds[fill[p.first]++] = p.second;
  IndexPairs pairs;
  pairs.reserve(ranked.size());
  for (std::size_t r = 0; r + 1 < start.size(); ++r) {
    const auto first = seconds.begin() + start[r], last = seconds.begin() + start[r + 1];
    std::sort(first, last);
    for (auto it = first; it != last; ++it)
      if (it == first || *it != *(it - 1))
        pairs.emplace_back(index_of_rank[0][r], index_of_rank[1][*it]);
  }
  return pairs;
}

// Every meeting pair of boxes, of different sides where `bipartite`, as (side 0, side 1) or
// (lower index, higher), sorted, once: a sweep along the axis of least overlap, testing each
// box against the boxes still open there. O(n log n + n m + k) for m open at a time.
template <int Dimensions>
IndexPairs sweep_pairs(std::vector<Bounds<Dimensions>> boxes, bool bipartite) {
  // Ranks of the indices per side (one side where not bipartite): the pairs are sorted by them.
  std::array<std::vector<std::size_t>, 2> index_of_rank;
  for (const auto& b : boxes) index_of_rank[bipartite ? b.side : 0].push_back(b.index);
  for (auto& indices : index_of_rank) {
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  }
  for (auto& b : boxes) {
    const auto& indices = index_of_rank[bipartite ? b.side : 0];
    b.rank =
        std::uint32_t(std::lower_bound(indices.begin(), indices.end(), b.index) - indices.begin());
  }
  if (!bipartite) index_of_rank[1] = index_of_rank[0];
  const int axis = sweep_axis(boxes);
  std::sort(boxes.begin(), boxes.end(), [&](const auto& a, const auto& b) {
    return std::tie(a.low[axis], a.side, a.index) < std::tie(b.low[axis], b.side, b.index);
  });
  const auto meet = [&](const auto& a, const auto& b) {
    for (int k = 0; k < Dimensions; ++k)
      if (a.high[k] < b.low[k] || b.high[k] < a.low[k]) return false;
    return true;
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ranked;
  // The boxes still open, per side (one where not bipartite): copies, side by side in memory.
  std::array<std::vector<Bounds<Dimensions>>, 2> open;
  for (const auto& b : boxes) {
    // A box meets the open boxes of the other side (of its own where not bipartite).
    std::vector<Bounds<Dimensions>>& others = open[bipartite ? 1 - b.side : 0];
    std::erase_if(others, [&](const auto& a) { return a.high[axis] < b.low[axis]; });
    for (const auto& a : others) {
      if (a.index == b.index && !bipartite) continue;
      if (!meet(a, b)) continue;
      if (bipartite)
        ranked.emplace_back(a.side == 0 ? a.rank : b.rank, a.side == 0 ? b.rank : a.rank);
      else ranked.emplace_back(std::min(a.rank, b.rank), std::max(a.rank, b.rank));
    }
    open[bipartite ? b.side : 0].push_back(b);
  }
  return sorted_index_pairs(ranked, index_of_rank);
}

template <class Box>
IndexPairs meeting_pairs(const std::vector<Box>& boxes) {
  if (boxes.size() < kSweepBelow) {
    std::vector<decltype(bounds_of(Box{}, 0))> all;
    all.reserve(boxes.size());
    for (const Box& b : boxes) all.push_back(bounds_of(b, 0));
    return sweep_pairs(std::move(all), false);
  }
  auto cgal = to_cgal(boxes, 0);
  IndexPairs pairs;
  CGAL::box_self_intersection_d(cgal.begin(), cgal.end(), [&](const auto& a, const auto& b) {
    const std::size_t i = a.info() >> 1;
    const std::size_t j = b.info() >> 1;
    pairs.emplace_back(std::min(i, j), std::max(i, j));
  });
  sort_unique(pairs);
  return pairs;
}

template <class Box>
IndexPairs meeting_pairs(const std::vector<Box>& left, const std::vector<Box>& right) {
  if (left.size() + right.size() < kSweepBelow) {
    std::vector<decltype(bounds_of(Box{}, 0))> all;
    all.reserve(left.size() + right.size());
    for (const Box& b : left) all.push_back(bounds_of(b, 0));
    for (const Box& b : right) all.push_back(bounds_of(b, 1));
    return sweep_pairs(std::move(all), true);
  }
  auto a = to_cgal(left, 0);
  auto b = to_cgal(right, 1);
  IndexPairs pairs;
  CGAL::box_intersection_d(
      a.begin(), a.end(), b.begin(), b.end(), [&](const auto& x, const auto& y) {
        const bool x_left = (x.info() & 1) == 0;
        pairs.emplace_back((x_left ? x : y).info() >> 1, (x_left ? y : x).info() >> 1);
      });
  sort_unique(pairs);
  return pairs;
}

}  // namespace

IndexPairs find_meeting_boxes(const std::vector<Box2>& boxes) { return meeting_pairs(boxes); }

IndexPairs find_meeting_boxes(const std::vector<Box2>& left, const std::vector<Box2>& right) {
  return meeting_pairs(left, right);
}

IndexPairs find_meeting_boxes(const std::vector<SpaceBox>& boxes) { return meeting_pairs(boxes); }

IndexPairs find_meeting_boxes(const std::vector<SpaceBox>& left,
                              const std::vector<SpaceBox>& right) {
  return meeting_pairs(left, right);
}

Box2 grown_segment_box(double ax, double ay, double bx, double by, double margin) {
  // One step outward after each rounded sum keeps the box conservative.
  const double inf = std::numeric_limits<double>::infinity();
  return Box2{std::nextafter(std::min(ax, bx) - margin, -inf),
              std::nextafter(std::min(ay, by) - margin, -inf),
              std::nextafter(std::max(ax, bx) + margin, inf),
              std::nextafter(std::max(ay, by) + margin, inf), 0};
}

SpaceBox space_box(const Box2& plan, double z0, double z1) {
  const double most = std::numeric_limits<double>::max();
  if (!std::isfinite(z0) || !std::isfinite(z1)) return {plan, -most, most};
  const double inf = std::numeric_limits<double>::infinity();
  return {plan, std::max(std::nextafter(std::min(z0, z1), -inf), -most),
          std::min(std::nextafter(std::max(z0, z1), inf), most)};
}

}  // namespace roomcad
