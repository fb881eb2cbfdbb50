// SPDX-License-Identifier: GPL-3.0-or-later
// A uniform 2D grid of boxes: the broad phase of hidden-line removal (which edges can cross an
// edge, which faces can cover a point), so no step compares all pairs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "plan/plan.h"

namespace roomcad::detail {

struct Box2 {
  Point2 min{1e300, 1e300};
  Point2 max{-1e300, -1e300};
  void add(Point2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  [[nodiscard]] bool is_empty() const { return min.x > max.x || min.y > max.y; }
};

/// @return the smallest box holding both. O(1).
inline Box2 merge_boxes(const Box2& a, const Box2& b) {
  Box2 out = a;
  if (!b.is_empty()) {
    out.add(b.min);
    out.add(b.max);
  }
  return out;
}

/// Ids of boxes by the cells they overlap. Cells are square, about `target_per_cell` boxes'
/// worth of area each; a box is clamped to the grid's bounds.
class BoxGrid {
 public:
  /// @param bounds  the area queried, non-empty; @param count  boxes expected (sizes the grid)
  BoxGrid(const Box2& bounds, std::size_t count) : bounds_(bounds) {
    const double w = std::max(bounds.max.x - bounds.min.x, 1e-9);
    const double h = std::max(bounds.max.y - bounds.min.y, 1e-9);
    const double cells = std::clamp(static_cast<double>(count), 1.0, 1e6);
    cell_ = std::sqrt(w * h / cells);
    nx_ = std::clamp(static_cast<int>(w / cell_) + 1, 1, 1024);
    ny_ = std::clamp(static_cast<int>(h / cell_) + 1, 1, 1024);
    cell_ = std::max(w / nx_, h / ny_) * (1.0 + 1e-9);
    cells_.resize(static_cast<std::size_t>(nx_) * ny_);
  }

  void insert(const Box2& box, std::uint32_t id) {
    for_cells(box, [&](std::vector<std::uint32_t>& cell) { cell.push_back(id); });
  }

  /// Ids of boxes that may overlap `box`, each once, in increasing order (deterministic).
  /// O(cells covered + ids found * log).
  void query(const Box2& box, std::vector<std::uint32_t>& out) const {
    out.clear();
    for_cells(box, [&](const std::vector<std::uint32_t>& cell) {
      out.insert(out.end(), cell.begin(), cell.end());
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

 private:
  int clamp_x(double x) const {
    return std::clamp(static_cast<int>(std::floor((x - bounds_.min.x) / cell_)), 0, nx_ - 1);
  }
  int clamp_y(double y) const {
    return std::clamp(static_cast<int>(std::floor((y - bounds_.min.y) / cell_)), 0, ny_ - 1);
  }
  template <class Cells, class F>
  static void visit(Cells& cells, int nx, int x0, int y0, int x1, int y1, F&& f) {
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) f(cells[static_cast<std::size_t>(y) * nx + x]);
  }
  template <class F>
  void for_cells(const Box2& b, F&& f) {
    visit(cells_, nx_, clamp_x(b.min.x), clamp_y(b.min.y), clamp_x(b.max.x), clamp_y(b.max.y), f);
  }
  template <class F>
  void for_cells(const Box2& b, F&& f) const {
    visit(cells_, nx_, clamp_x(b.min.x), clamp_y(b.min.y), clamp_x(b.max.x), clamp_y(b.max.y), f);
  }

  Box2 bounds_;
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
};

}  // namespace roomcad::detail
