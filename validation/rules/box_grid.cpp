// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/box_grid.h"

#include <algorithm>
#include <cmath>

namespace roomcad::rules {

BoxGrid::BoxGrid(std::vector<Box2> boxes) : boxes_(std::move(boxes)) {
  double size = 0.0;
  for (const Box2& b : boxes_) size += (b.max_x - b.min_x) + (b.max_y - b.min_y);
  if (!boxes_.empty() && size > 0.0) cell_ = std::max(size / (2.0 * static_cast<double>(boxes_.size())), 1e-3);
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const Box2& b = boxes_[i];
    if ((cell_of(b.max_x) - cell_of(b.min_x) + 1) * (cell_of(b.max_y) - cell_of(b.min_y) + 1) > 4096) {
      big_.push_back(i);
      continue;
    }
    for (long long cx = cell_of(b.min_x); cx <= cell_of(b.max_x); ++cx)
      for (long long cy = cell_of(b.min_y); cy <= cell_of(b.max_y); ++cy) cells_[key_of(cx, cy)].push_back(i);
  }
}

long long BoxGrid::cell_of(double v) const {
  // Clamped so that a huge query box cannot loop for ever; boxes beyond share the edge cells.
  // fmax takes the bound for NaN (a box of NaN meets nothing), where a cast would be undefined.
  return static_cast<long long>(std::fmin(std::fmax(std::floor(v / cell_), -1e6), 1e6));
}

std::vector<std::size_t> BoxGrid::find(const Box2& q) const {
  std::vector<std::size_t> out;
  const long long x0 = cell_of(q.min_x), x1 = cell_of(q.max_x), y0 = cell_of(q.min_y), y1 = cell_of(q.max_y);
  const auto visit = [&](std::size_t i) {
    const Box2& b = boxes_[i];
    if (b.min_x <= q.max_x && q.min_x <= b.max_x && b.min_y <= q.max_y && q.min_y <= b.max_y)
      out.push_back(b.index);
  };
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > static_cast<long long>(boxes_.size())) {
    for (std::size_t i = 0; i < boxes_.size(); ++i) visit(i);  // the query covers everything
  } else {
    for (long long cx = x0; cx <= x1; ++cx)
      for (long long cy = y0; cy <= y1; ++cy)
        if (const auto it = cells_.find(key_of(cx, cy)); it != cells_.end())
          for (const std::size_t i : it->second) visit(i);
    for (const std::size_t i : big_) visit(i);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace roomcad::rules
