// SPDX-License-Identifier: GPL-3.0-or-later
// Which of a set of boxes in a plane meet a query box, without testing them all: a uniform
// grid of about one cell per box over their extent. A plane of a tall building holds a hundred
// polygons side by side and storey over storey; each of its pieces meets a handful of them.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace roomcad::detail {

/// A closed box: low x, low y, high x, high y. The bounds of an exact point's interval may be
/// infinite or NaN (a corner of nearly parallel planes).
using Bounds = std::array<double, 4>;

/// @return whether closed boxes a and b meet. No comparison with NaN is true, so a box with a
/// NaN bound meets every box.
[[nodiscard]] inline bool boxes_meet(const Bounds& a, const Bounds& b) {
  return !(a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1]);
}

class BoundsGrid {
 public:
  /// Most cells a box is filed in, on average, before the grid is given up for one cell.
  static constexpr std::size_t kMaxFiledPerBox = 16;

  /// Files every box by the cells it covers. O(n) time and memory: on average a box covers
  /// at most kMaxFiledPerBox cells, or the grid is one cell.
  explicit BoundsGrid(const std::vector<Bounds>& boxes);

  /// Calls `visit(k)` once for every box k that meets `query` (boxes_meet), in no set order.
  /// O(cells covered by the query + boxes filed there).
  template <class Visit>
  void for_each_meeting(const Bounds& query, Visit&& visit) {
    ++stamp_;
    auto consider = [&](std::uint32_t k) {
      if (seen_[k] == stamp_) return;
      seen_[k] = stamp_;
      if (boxes_meet(query, boxes_[k])) visit(std::size_t(k));
    };
    for (const std::uint32_t k : everywhere_) consider(k);
    const Cells covered = cells_of(query);
    if (!covered.valid()) {  // NaN or low above high: considered against every box
      for (std::uint32_t k = 0; k < boxes_.size(); ++k) consider(k);
      return;
    }
    for_each_cell(covered, [&](std::size_t cell) {
      for (std::uint32_t at = first_[cell]; at < first_[cell + 1]; ++at) consider(filed_[at]);
    });
  }

 private:
  struct Span {
    int low = 0, high = 0;
    bool valid = true;
  };
  /// The cells [low, high] along `axis` that [from, to] covers (clamped to the grid); not
  /// valid when a bound is NaN or from > to, which boxes_meet does not read as empty.
  /// Monotone in the coordinate, so boxes that share a point share a cell; compared as doubles
  /// before the cast, so an infinite bound never reaches it.
  [[nodiscard]] Span span(double from, double to, std::size_t axis) const {
    if (!(from <= to)) return {0, 0, false};
    auto cell = [&](double v) {
      const double t = (v - origin_[axis]) / cell_[axis];
      if (!(t >= 0.0)) return 0;
      if (t >= double(side_ - 1)) return side_ - 1;
      return int(t);
    };
    return {cell(from), cell(to), true};
  }

  /// The cells a box covers, along x and along y.
  struct Cells {
    Span x, y;
    [[nodiscard]] bool valid() const { return x.valid && y.valid; }
    [[nodiscard]] std::size_t count() const {
      return std::size_t(x.high - x.low + 1) * std::size_t(y.high - y.low + 1);
    }
  };
  [[nodiscard]] Cells cells_of(const Bounds& b) const { return {span(b[0], b[2], 0), span(b[1], b[3], 1)}; }
  /// Calls `f(cell)` with the index of every cell in `covered` (valid).
  template <class F>
  void for_each_cell(const Cells& covered, F&& f) const {
    for (int cy = covered.y.low; cy <= covered.y.high; ++cy)
      for (int cx = covered.x.low; cx <= covered.x.high; ++cx)
        f(std::size_t(cy) * std::size_t(side_) + std::size_t(cx));
  }

  const std::vector<Bounds>& boxes_;
  int side_ = 1;                            // cells along each axis
  std::array<double, 2> origin_{}, cell_{};  // the grid's low corner and cell size
  std::vector<std::uint32_t> first_;        // per cell, where its boxes start in filed_
  std::vector<std::uint32_t> filed_;        // box indices, cell by cell
  std::vector<std::uint32_t> everywhere_;   // boxes with no valid span: tested by every query
  std::vector<std::uint32_t> seen_;         // per box, the last query that considered it
  std::uint32_t stamp_ = 0;
};

}  // namespace roomcad::detail
