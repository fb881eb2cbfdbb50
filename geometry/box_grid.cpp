// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/box_grid.h"

#include <algorithm>
#include <cmath>

namespace roomcad {

BoxGrid::BoxGrid(std::vector<Box2> boxes) : boxes_(std::move(boxes)), seen_(boxes_.size(), 0) {
  // The extent of the finite bounds; infinite ones are clamped to the grid's edge cells.
  std::array<double, 2> low{INFINITY, INFINITY}, high{-INFINITY, -INFINITY};
  for (const Box2& b : boxes_)
    for (const auto& [a, v] : {std::pair{0, b.min_x}, std::pair{0, b.max_x}, std::pair{1, b.min_y},
                               std::pair{1, b.max_y}})
      if (std::isfinite(v)) low[a] = std::min(low[a], v), high[a] = std::max(high[a], v);
  auto set_side = [&](int side) {
    side_ = side;
    for (std::size_t a = 0; a < 2; ++a) {
      origin_[a] = low[a] <= high[a] ? low[a] : 0.0;
      cell_[a] = low[a] < high[a] ? (high[a] - low[a]) / side_ : 1.0;
    }
  };
  set_side(std::clamp(int(std::ceil(std::sqrt(double(boxes_.size())))), 1, 64));
  auto cover = [&] {
    std::vector<Cells> covered;
    covered.reserve(boxes_.size());
    for (const Box2& b : boxes_) covered.push_back(cells_of(b));
    return covered;
  };
  std::vector<Cells> covered = cover();
  // Boxes that each cover much of the grid (polygons drawn over one another) would be filed
  // in n cells each: past kMaxFiledPerBox on average, one cell holds them all (a scan, as
  // without a grid), so memory stays linear in the boxes.
  std::size_t filed = 0;
  for (const Cells& c : covered)
    if (c.valid()) filed += c.count();
  if (filed > kMaxFiledPerBox * boxes_.size()) {
    set_side(1);
    covered = cover();
  }
  // Count, then file: each box in every cell its bounds cover.
  const std::size_t cells = std::size_t(side_) * std::size_t(side_);
  first_.assign(cells + 1, 0);
  for (std::uint32_t k = 0; k < boxes_.size(); ++k) {
    if (!covered[k].valid()) everywhere_.push_back(k);
    else for_each_cell(covered[k], [&](std::size_t cell) { ++first_[cell + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) first_[c + 1] += first_[c];
  filed_.resize(first_[cells]);
  std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
  for (std::uint32_t k = 0; k < boxes_.size(); ++k)
    if (covered[k].valid())
      for_each_cell(covered[k], [&](std::size_t cell) { filed_[next[cell]++] = k; });
}

BoxGrid::Span BoxGrid::span(double from, double to, std::size_t axis) const {
  if (!(from <= to)) return {0, 0, false};
  auto cell = [&](double v) {
    const double t = (v - origin_[axis]) / cell_[axis];
    if (!(t >= 0.0)) return 0;
    if (t >= double(side_ - 1)) return side_ - 1;
    return int(t);
  };
  return {cell(from), cell(to), true};
}

void BoxGrid::find(const Box2& query, std::vector<std::size_t>& out) const {
  out.clear();
  for_each_candidate(query, [&](std::uint32_t k) {
    if (boxes_meet(query, boxes_[k])) out.push_back(boxes_[k].index);
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace roomcad
