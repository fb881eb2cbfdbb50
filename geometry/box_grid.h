// SPDX-License-Identifier: GPL-3.0-or-later
// Which of a set of boxes meet a query box, without testing them all: a uniform grid of about
// one cell per box over their extent. The one box grid of the tree: a plane of the solid
// kernel's general path (its polygons, storey over storey), a drawing's hidden-line removal
// (its edges and faces in the picture) and the rule checks (walls near a door) all ask it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/box.h"

namespace roomcad {

class BoxGrid {
 public:
  /// Most cells a box is filed in, on average, before the grid is given up for one cell.
  static constexpr std::size_t kMaxFiledPerBox = 16;

  /// A grid of no boxes: every query finds nothing.
  BoxGrid() = default;

  /// Files every box by the cells it covers. A box with a NaN bound, or a min above its max,
  /// is tested by every query. O(n) time and memory: on average a box covers at most
  /// kMaxFiledPerBox cells, or the grid is one cell.
  explicit BoxGrid(std::vector<Box2> boxes);

  [[nodiscard]] std::size_t size() const { return boxes_.size(); }

  /// Calls `visit(index)` once for the Box2::index of every box that meets `query`
  /// (boxes_meet), in an order fixed by the boxes and the query. Not for several threads at
  /// once (it marks the boxes it visits); find is. O(cells the query covers + boxes filed
  /// there).
  template <class Visit>
  void for_each_meeting(const Box2& query, Visit&& visit) {
    ++stamp_;
    auto consider = [&](std::uint32_t k) {
      if (seen_[k] == stamp_) return;
      seen_[k] = stamp_;
      if (boxes_meet(query, boxes_[k])) visit(boxes_[k].index);
    };
    for_each_candidate(query, consider);
  }

  /// @return the Box2::index of every box that meets `query`, sorted, each once, in `out`.
  ///         Safe from several threads at once. O(cells covered + boxes filed there, log).
  void find(const Box2& query, std::vector<std::size_t>& out) const;
  [[nodiscard]] std::vector<std::size_t> find(const Box2& query) const {
    std::vector<std::size_t> out;
    find(query, out);
    return out;
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
  [[nodiscard]] Span span(double from, double to, std::size_t axis) const;

  /// The cells a box covers, along x and along y.
  struct Cells {
    Span x, y;
    [[nodiscard]] bool valid() const { return x.valid && y.valid; }
    [[nodiscard]] std::size_t count() const {
      return std::size_t(x.high - x.low + 1) * std::size_t(y.high - y.low + 1);
    }
  };
  [[nodiscard]] Cells cells_of(const Box2& b) const {
    return {span(b.min_x, b.max_x, 0), span(b.min_y, b.max_y, 1)};
  }
  /// Calls `f(cell)` with the index of every cell in `covered` (valid).
  template <class F>
  void for_each_cell(const Cells& covered, F&& f) const {
    for (int cy = covered.y.low; cy <= covered.y.high; ++cy)
      for (int cx = covered.x.low; cx <= covered.x.high; ++cx)
        f(std::size_t(cy) * std::size_t(side_) + std::size_t(cx));
  }
  /// Calls `f(k)` for every box k filed where `query` may meet it (some more than once).
  template <class F>
  void for_each_candidate(const Box2& query, F&& f) const {
    for (const std::uint32_t k : everywhere_) f(k);
    const Cells covered = cells_of(query);
    if (!covered.valid()) {  // NaN or low above high: considered against every box
      for (std::uint32_t k = 0; k < boxes_.size(); ++k) f(k);
      return;
    }
    for_each_cell(covered, [&](std::size_t cell) {
      for (std::uint32_t at = first_[cell]; at < first_[cell + 1]; ++at) f(filed_[at]);
    });
  }

  std::vector<Box2> boxes_;
  int side_ = 1;                                     // cells along each axis
  std::array<double, 2> origin_{}, cell_{1.0, 1.0};  // the grid's low corner and cell size
  std::vector<std::uint32_t> first_{0, 0};           // per cell, where its boxes start in filed_
  std::vector<std::uint32_t> filed_;                 // box positions, cell by cell
  std::vector<std::uint32_t> everywhere_;  // boxes with no valid span: tested by every query
  std::vector<std::uint32_t> seen_;        // per box, the last query that considered it
  std::uint32_t stamp_ = 0;
};

}  // namespace roomcad
