// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/equal_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "core/flat_index.h"

namespace roomcad::detail {
namespace {

// Calls f(cell) for each cell of a fine square grid in the view axes (side `cell`) that point
// p's bounds cover, at most four, and returns true; false (no calls) when they cover more or
// are not finite. Equal points have overlapping bounds, so they share a cell: rounded
// division and floor are monotone, so the cell of the higher of the two low bounds is in both.
template <class F>
bool for_each_fine_cell(int i, int j, const XPoint& p, double cell, F&& f) {
  const auto [li, hi] = bounds(p, i);
  const auto [lj, hj] = bounds(p, j);
  const double i0 = std::floor(li / cell), i1 = std::floor(hi / cell);
  const double j0 = std::floor(lj / cell), j1 = std::floor(hj / cell);
  if (!(i1 - i0 <= 1.0 && j1 - j0 <= 1.0)) return false;  // NaN and infinite bounds too
  for (double ci = i0; ci <= i1; ++ci)
    for (double cj = j0; cj <= j1; ++cj)
      f(std::array<std::uint64_t, 2>{std::uint64_t(std::int64_t(ci)),
                                     std::uint64_t(std::int64_t(cj))});
  return true;
}

}  // namespace

std::vector<std::size_t> find_equal_points(PointCache& points, int i, int j) {
  const std::size_t n = points.size();
  double largest = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    for (const int axis : {i, j})
      for (const double v : {bounds(points[k], axis).first, bounds(points[k], axis).second})
        if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  const double cell = std::max(largest * 0x1p-24, std::numeric_limits<double>::min());
  // Equal points united (a union-find forest), cell by cell.
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  const auto unite_if_same = [&](std::size_t a, std::size_t b) {
    const std::size_t ra = root(a), rb = root(b);
    if (ra != rb && points.is_same(a, b)) parent[std::max(ra, rb)] = std::min(ra, rb);
  };
  using CellKey = std::array<std::uint64_t, 2>;
  FlatIndex<CellKey> cell_of(n);
  std::vector<std::uint32_t> last_in_cell;                   // per cell, its last filed entry
  std::vector<std::pair<std::size_t, std::uint32_t>> filed;  // (point, the cell's entry before it)
  std::vector<std::size_t> wide;
  for (std::size_t k = 0; k < n; ++k) {
    const bool fine = for_each_fine_cell(i, j, points[k], cell, [&](const CellKey& key) {
      const auto [c, added] = cell_of.try_emplace(key, std::uint32_t(last_in_cell.size()));
      if (added) last_in_cell.push_back(FlatIndex<CellKey>::kNone);
      for (std::uint32_t e = last_in_cell[c]; e != FlatIndex<CellKey>::kNone; e = filed[e].second)
        unite_if_same(k, filed[e].first);
      filed.emplace_back(k, last_in_cell[c]);
      last_in_cell[c] = std::uint32_t(filed.size() - 1);
    });
    if (!fine) wide.push_back(k);
  }
  for (const std::size_t w : wide)
    for (std::size_t k = 0; k < n; ++k)
      if (k != w) unite_if_same(w, k);
  // Each group's representative: its first point in order of low bound, then index.
  const auto earlier = [&](std::size_t a, std::size_t b) {
    const double la = bounds(points[a], i).first, lb = bounds(points[b], i).first;
    return la < lb || (la == lb && a < b);
  };
  std::vector<std::size_t> first_of_group(n, n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t& first = first_of_group[root(k)];
    if (first == n || earlier(k, first)) first = k;
  }
  std::vector<std::size_t> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = first_of_group[root(k)];
  return out;
}

}  // namespace roomcad::detail
