// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/detail/bounds_grid.h"

#include <algorithm>

namespace roomcad::detail {

BoundsGrid::BoundsGrid(const std::vector<Bounds>& boxes) : boxes_(boxes), seen_(boxes.size(), 0) {
  // The extent of the finite bounds; infinite ones are clamped to the grid's edge cells.
  std::array<double, 2> low{INFINITY, INFINITY}, high{-INFINITY, -INFINITY};
  for (const Bounds& b : boxes)
    for (std::size_t a = 0; a < 2; ++a)
      for (const double v : {b[a], b[a + 2]})
        if (std::isfinite(v)) low[a] = std::min(low[a], v), high[a] = std::max(high[a], v);
  auto set_side = [&](int side) {
    side_ = side;
    for (std::size_t a = 0; a < 2; ++a) {
      origin_[a] = low[a] <= high[a] ? low[a] : 0.0;
      cell_[a] = low[a] < high[a] ? (high[a] - low[a]) / side_ : 1.0;
    }
  };
  set_side(std::clamp(int(std::ceil(std::sqrt(double(boxes.size())))), 1, 64));
  // Boxes that each cover much of the grid (polygons drawn over one another) would be filed
  // in n cells each: past kMaxFiledPerBox on average, one cell holds them all (a scan, as
  // without a grid), so memory stays linear in the boxes.
  std::size_t filed = 0;
  for (const Bounds& b : boxes) {
    const Span x = span(b[0], b[2], 0), y = span(b[1], b[3], 1);
    if (x.valid && y.valid) filed += std::size_t(x.high - x.low + 1) * std::size_t(y.high - y.low + 1);
  }
  if (filed > kMaxFiledPerBox * boxes.size()) set_side(1);
  // Count, then file: each box in every cell its bounds cover.
  const std::size_t cells = std::size_t(side_) * std::size_t(side_);
  first_.assign(cells + 1, 0);
  auto each_cell = [&](const Bounds& b, auto&& f) {
    const Span x = span(b[0], b[2], 0), y = span(b[1], b[3], 1);
    for (int cy = y.low; cy <= y.high; ++cy)
      for (int cx = x.low; cx <= x.high; ++cx) f(std::size_t(cy) * std::size_t(side_) + std::size_t(cx));
  };
  for (std::uint32_t k = 0; k < boxes.size(); ++k) {
    if (!span(boxes[k][0], boxes[k][2], 0).valid || !span(boxes[k][1], boxes[k][3], 1).valid)
      everywhere_.push_back(k);
    else
      each_cell(boxes[k], [&](std::size_t cell) { ++first_[cell + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) first_[c + 1] += first_[c];
  filed_.resize(first_[cells]);
  std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
  std::size_t nowhere = 0;  // the next box of everywhere_, which is filed in no cell
  for (std::uint32_t k = 0; k < boxes.size(); ++k) {
    if (nowhere < everywhere_.size() && everywhere_[nowhere] == k) {
      ++nowhere;
      continue;
    }
    each_cell(boxes[k], [&](std::size_t cell) { filed_[next[cell]++] = k; });
  }
}

}  // namespace roomcad::detail
