// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/grid_faces.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <optional>
#include <span>
#include <tuple>

#include "core/flat_index.h"
#include "solid/detail/general_path/convex_pieces.h"
#include "solid/detail/general_path/grid_tracing.h"
#include "solid/detail/general_path/wedges_apart.h"

namespace roomcad::detail {
namespace {

using grid::face_corners;
using grid::find_regions;
using grid::Grid;
using grid::Region;
using grid::region_loops;
using grid::Step;
using grid::TraceScratch;

// An interval is [0, 0] only where the value it encloses is 0.
bool is_zero(const Interval& x) { return x.inf() == 0.0 && x.sup() == 0.0; }

// Which coordinate of the plane's view (axes i, j) is constant along line t's trace: the
// trace runs along n x n_t, whose j part is 0 where j is constant. 0: i (a line across the
// view's i axis), 1: j, -1: neither, or not known from the intervals (then the general
// boolean decides).
int constant_axis(const PlaneSet& set, PlaneId plane, PlaneId t, int i, int j) {
  const auto& n = set.approx(plane);
  const auto& m = set.approx(t);
  const auto cross = [&](int a) {
    const auto b = std::size_t((a + 1) % 3), c = std::size_t((a + 2) % 3);
    return n[b] * m[c] - n[c] * m[b];
  };
  if (is_zero(cross(i))) return 0;
  if (is_zero(cross(j))) return 1;
  return -1;
}

void sort_unique(std::vector<PlaneId>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// The lines of one direction in order along the plane; lines with the same trace share a rank.
class LineOrder {
 public:
  /// @param[in] lines  distinct ids, sorted
  /// @param[in] at     at[k]: the index in `points` of a point of lines[k], all of them on one
  ///                   line across these
  /// @param[in] axis   the coordinate the points are ordered by
  LineOrder(std::vector<PlaneId> lines, const std::vector<std::size_t>& at, PointCache& points,
            int axis)
      : ids_(std::move(lines)), rank_of_(ids_.size()) {
    std::vector<std::size_t> order(ids_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const int c = points.compare(at[a], at[b], axis);
      return c < 0 || (c == 0 && ids_[a] < ids_[b]);
    });
    for (std::size_t m = 0; m < order.size(); ++m) {
      if (m == 0 || points.compare(at[order[m - 1]], at[order[m]], axis) != 0) {
        line_of_rank_.push_back(ids_[order[m]]);
        point_of_rank_.push_back(at[order[m]]);
        shared_.push_back(0);
      } else {
        shared_.back() = 1;
      }
      rank_of_[order[m]] = std::uint32_t(line_of_rank_.size() - 1);
    }
  }
  /// @return whether two or more lines (planes) have the trace of that rank.
  [[nodiscard]] bool is_shared(std::size_t rank) const { return shared_[rank] != 0; }
  /// @pre `line` is one of the lines.
  [[nodiscard]] std::uint32_t rank(PlaneId line) const {
    return rank_of_[std::size_t(std::lower_bound(ids_.begin(), ids_.end(), line) - ids_.begin())];
  }
  [[nodiscard]] std::size_t size() const { return line_of_rank_.size(); }
  /// @return the lowest id of the lines of that rank.
  [[nodiscard]] PlaneId line(std::size_t rank) const { return line_of_rank_[rank]; }
  /// @return the index in the points of a point of the lines of that rank.
  [[nodiscard]] std::size_t point(std::size_t rank) const { return point_of_rank_[rank]; }

 private:
  std::vector<PlaneId> ids_;
  std::vector<std::uint32_t> rank_of_;  // per ids_[k]
  std::vector<PlaneId> line_of_rank_;
  std::vector<std::size_t> point_of_rank_;
  std::vector<char> shared_;  // per rank
};

// A polygon's block of cells: between the lines u0 < u1 of constant u and v0 < v1 of
// constant v (their ranks).
struct Block {
  std::uint32_t u0, u1, v0, v1;
};

// The sign of coefficient k of a plane's normal. @pre not 0.
int coefficient_sign(const PlaneSet& set, PlaneId id, int k) {
  const Interval& x = set.approx(id)[std::size_t(k)];
  if (x.inf() > 0.0) return 1;
  if (x.sup() < 0.0) return -1;
  return set.exact(id)[std::size_t(k)].sign() > 0 ? 1 : -1;
}

// The plane's grid: its lines of each direction in order, the cells' owners, and the points
// made on it (corners of cells, vertices of faces), each made once.
class PlaneGrid {
 public:
  PlaneGrid(const PlaneSet& set, PlaneRef plane, int k, std::array<std::vector<PlaneId>, 2> lines)
      : set_(set),
        plane_(plane),
        i_((k + 1) % 3),
        j_((k + 2) % 3),
        points_(set),
        us_(order(lines, 0)),
        vs_(order(lines, 1)),
        grid_{us_.size(), vs_.size(), {}, {}, {}},
        made_(grid_.nu * grid_.nv, kNotMade) {}

  [[nodiscard]] const LineOrder& us() const { return us_; }
  [[nodiscard]] const LineOrder& vs() const { return vs_; }
  [[nodiscard]] Grid& grid() { return grid_; }
  [[nodiscard]] PointCache& points() { return points_; }
  [[nodiscard]] int axis(int family) const { return family == 0 ? i_ : j_; }
  [[nodiscard]] std::size_t cells() const { return (grid_.nu - 1) * (grid_.nv - 1); }

  /// @return the index in points() of grid point (u, v), made on first need.
  std::size_t corner(std::uint32_t u, std::uint32_t v) {
    std::uint32_t& m = made_[grid_.point(u, v)];
    if (m == kNotMade)
      m = std::uint32_t(points_.add(make_point(set_, plane_.id, us_.line(u), vs_.line(v))));
    return m;
  }

  /// The line of constant u (family 0) or v (1) of that rank, oriented so that the cells of
  /// higher ranks (`above`) or lower ones lie on its negative side.
  PlaneRef bounding(int family, std::uint32_t rank, bool above) {
    const PlaneId line = family == 0 ? us_.line(rank) : vs_.line(rank);
    // A point of the next (or previous) line of the family: inside.
    const std::uint32_t other = above ? rank + 1 : rank - 1;
    const std::size_t at = family == 0 ? corner(other, 0) : corner(0, other);
    return {line, points_.side({line, 1}, at) < 0 ? 1 : -1};
  }

 private:
  static constexpr std::uint32_t kNotMade = UINT32_MAX;

  // The family's lines in order, at their points on the first line of the other family.
  LineOrder order(const std::array<std::vector<PlaneId>, 2>& lines, int family) {
    std::vector<std::size_t> at;
    const std::vector<PlaneId>& mine = lines[std::size_t(family)];
    const PlaneId across = lines[std::size_t(1 - family)].front();
    for (const PlaneId t : mine)
      at.push_back(points_.add(family == 0 ? make_point(set_, plane_.id, t, across)
                                           : make_point(set_, plane_.id, across, t)));
    return LineOrder(mine, at, points_, axis(family));
  }

  const PlaneSet& set_;
  PlaneRef plane_;
  int i_, j_;
  PointCache points_;
  LineOrder us_, vs_;
  Grid grid_;
  std::vector<std::uint32_t> made_;  // per grid point: its index in points_
};

// How a polygon lies over a cell.
enum class Cover : std::uint8_t { outside, inside, part };

// The cell's cover by a convex polygon, from its four corners against the polygon's lines:
// inside when they all are (the polygon is convex), outside when they all lie beyond one line.
Cover cover_of(PlaneGrid& pg, const PlanePolygon& polygon, std::uint32_t u, std::uint32_t v) {
  const std::array<std::size_t, 4> corners{pg.corner(u, v), pg.corner(u + 1, v),
                                           pg.corner(u + 1, v + 1), pg.corner(u, v + 1)};
  bool inside = true;
  for (const PlaneRef& t : polygon.lines) {
    bool beyond = true;
    for (const std::size_t c : corners) {
      const int s = pg.points().side(t, c);
      inside = inside && s <= 0;
      beyond = beyond && s >= 0;
    }
    if (beyond) return Cover::outside;
  }
  return inside ? Cover::inside : Cover::part;
}

// The cells [first, last) of one family's lines that points may reach, from their intervals
// (all of them where those are not finite).
std::pair<std::uint32_t, std::uint32_t> reach(PlaneGrid& pg, std::span<const XPoint> points,
                                              int family) {
  const int axis = pg.axis(family);
  const LineOrder& lines = family == 0 ? pg.us() : pg.vs();
  double lo = INFINITY, hi = -INFINITY;
  for (const XPoint& p : points)
    lo = std::min(lo, bounds(p, axis).first), hi = std::max(hi, bounds(p, axis).second);
  const auto n = std::uint32_t(lines.size() - 1);
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0, n};
  std::uint32_t first = 0, last = n;
  const auto at = [&](std::uint32_t r) { return bounds(pg.points()[lines.point(r)], axis); };
  while (first + 1 < n && at(first + 1).second < lo) ++first;
  while (last > first + 1 && at(last - 1).first > hi) --last;
  return {first, last};
}

// The block of cells the points may reach.
Block reach(PlaneGrid& pg, std::span<const XPoint> points) {
  const auto [u0, u1] = reach(pg, points, 0);
  const auto [v0, v1] = reach(pg, points, 1);
  return {u0, u1, v0, v1};
}

bool share_a_cell(const Block& a, const Block& b) {
  return a.u0 < b.u1 && b.u0 < a.u1 && a.v0 < b.v1 && b.v0 < a.v1;
}

// Whether the polygon lies within the grid's outermost lines (the grid holds nothing beyond).
bool within(PlaneGrid& pg, const PlanePolygon& polygon) {
  PointCache& points = pg.points();
  for (const XPoint& p : polygon.vertices) {
    const std::size_t at = points.add(p);
    for (const int family : {0, 1}) {
      const LineOrder& lines = family == 0 ? pg.us() : pg.vs();
      const int axis = pg.axis(family);
      if (points.compare(at, lines.point(0), axis) < 0 ||
          points.compare(at, lines.point(lines.size() - 1), axis) > 0)
        return false;
    }
  }
  return true;
}

// A block of cells as a polygon of the plane, counter-clockwise seen from its positive side.
PlanePolygon block_polygon(PlaneGrid& pg, PlaneRef plane, int view_side, const Block& b) {
  std::array<PlaneRef, 4> lines{pg.bounding(0, b.u0, true), pg.bounding(1, b.v0, true),
                                pg.bounding(0, b.u1, false), pg.bounding(1, b.v1, false)};
  std::array<std::size_t, 4> corners{pg.corner(b.u0, b.v0), pg.corner(b.u1, b.v0),
                                     pg.corner(b.u1, b.v1), pg.corner(b.u0, b.v1)};
  if (view_side < 0) {  // counter-clockwise in the view is clockwise seen from the positive side
    lines = {lines[0], lines[3], lines[2], lines[1]};
    corners = {corners[3], corners[2], corners[1], corners[0]};
  }
  PlanePolygon p{plane, {lines.begin(), lines.end()}, {}};
  for (const std::size_t c : corners) p.vertices.push_back(pg.points()[c]);
  return p;
}

// What lies on the grid: each polygon's lines by the coordinate they fix (0: u, 1: v, -1:
// neither, a slanted edge), each rectangle's block, the windows around the slanted edges, and
// the cells outside them that the slanted polygons hold.
struct Layout {
  std::vector<std::vector<int>> kinds;
  std::vector<std::size_t> slanted;  // the polygons with a slanted edge, in order
  std::vector<Block> reach;          // per slanted polygon: the cells its corners may reach
  std::vector<std::optional<Block>> block_of;
  std::vector<Block> windows;   // no two share a cell
  std::vector<char> in_window;  // per cell
  std::vector<std::pair<std::size_t, std::size_t>>
      holds;  // (cell outside the windows, slanted polygon)
};

// The polygons' lines by the coordinate they fix, into kinds and slanted; @return the lines of
// each family, distinct.
std::array<std::vector<PlaneId>, 2> classify_lines(const PlaneSet& set, PlaneRef plane, int i,
                                                   int j,
                                                   const std::vector<Contribution>& contributions,
                                                   Layout& layout) {
  std::array<std::vector<PlaneId>, 2> lines;
  layout.kinds.resize(contributions.size());
  for (std::size_t c = 0; c < contributions.size(); ++c) {
    for (const PlaneRef& t : contributions[c].polygon.lines) {
      const int a = constant_axis(set, plane.id, t.id, i, j);
      layout.kinds[c].push_back(a);
      if (a >= 0) lines[std::size_t(a)].push_back(t.id);
    }
    if (std::find(layout.kinds[c].begin(), layout.kinds[c].end(), -1) != layout.kinds[c].end())
      layout.slanted.push_back(c);
  }
  for (std::vector<PlaneId>& l : lines) sort_unique(l);
  return lines;
}

// Whether every slanted polygon lies within the grid's outermost lines (the grid holds nothing
// beyond).
bool slanted_within(PlaneGrid& pg, const std::vector<Contribution>& contributions,
                    const Layout& layout) {
  return std::all_of(layout.slanted.begin(), layout.slanted.end(),
                     [&](std::size_t c) { return within(pg, contributions[c].polygon); });
}

// Each rectangle's block: a convex polygon whose edges run along the view's axes is the
// rectangle of its outermost lines. @return false for one that is not (no area between them),
// left to the general boolean; adds the cells covered to `work`.
bool find_blocks(PlaneGrid& pg, const std::vector<Contribution>& contributions, Layout& layout,
                 std::size_t& work) {
  layout.block_of.assign(contributions.size(), std::nullopt);
  std::vector<std::uint32_t> ranks;
  for (std::size_t c = 0; c < contributions.size(); ++c) {
    if (std::binary_search(layout.slanted.begin(), layout.slanted.end(), c)) continue;
    const std::vector<PlaneRef>& lines = contributions[c].polygon.lines;
    const std::vector<int>& kinds = layout.kinds[c];
    Block b{UINT32_MAX, 0, UINT32_MAX, 0};
    ranks.clear();
    for (std::size_t m = 0; m < lines.size(); ++m) {
      const std::uint32_t r = kinds[m] == 0 ? pg.us().rank(lines[m].id) : pg.vs().rank(lines[m].id);
      ranks.push_back(r);
      if (kinds[m] == 0) b.u0 = std::min(b.u0, r), b.u1 = std::max(b.u1, r);
      else b.v0 = std::min(b.v0, r), b.v1 = std::max(b.v1, r);
    }
    if (!(b.u0 < b.u1 && b.v0 < b.v1)) return false;
    for (std::size_t m = 0; m < ranks.size(); ++m)
      if (kinds[m] == 0 ? ranks[m] != b.u0 && ranks[m] != b.u1
                        : ranks[m] != b.v0 && ranks[m] != b.v1)
        return false;
    work += std::size_t(b.u1 - b.u0) * (b.v1 - b.v0);
    layout.block_of[c] = b;
  }
  return true;
}

// Whether two solid rectangles on one side of the plane abut along a grid line where they may
// touch only along it (wedges_apart): then the face across the line must end there, which the
// grid's cells cannot tell, so the plane is left to the general boolean (which decides it
// with every polygon there). Rectangles abutting on one plane (walls meeting square, mitred,
// stacked) share it and leave no gap. The bundled homes have up to 8 planes each that go to
// the general boolean so; on none of them is the solid pinched (other polygons fill the gap).
// Only grid lines that two or more planes share are looked at. O(n log n) for the n sides of
// rectangles on them, plus a test per pair meeting on one line.
bool may_be_pinched(PlaneGrid& pg, const PlaneSet& set, PlaneRef plane,
                    const std::vector<Contribution>& contributions, const Layout& layout) {
  struct Side {
    int family;
    std::uint32_t rank, from, to;  // the line, and the block's ranks along it
    bool starts;                   // the block lies beyond the line (else before it)
    std::size_t polygon;
    PlaneRef line, across;
  };
  std::vector<Side> sides;
  for (std::size_t c = 0; c < contributions.size(); ++c) {
    const std::optional<Block>& b = layout.block_of[c];
    if (!b || !contributions[c].solid) continue;
    const std::vector<PlaneRef>& lines = contributions[c].polygon.lines;
    const std::vector<int>& kinds = layout.kinds[c];
    for (std::size_t m = 0; m < lines.size(); ++m) {
      const int family = kinds[m];
      const LineOrder& order = family == 0 ? pg.us() : pg.vs();
      const std::uint32_t rank = order.rank(lines[m].id);
      if (!order.is_shared(rank)) continue;  // one plane there: rectangles abut on it
      // A line of the other family crosses this one.
      const auto other = std::find(kinds.begin(), kinds.end(), 1 - family);
      const PlaneRef across = lines[std::size_t(other - kinds.begin())];
      const std::uint32_t from = family == 0 ? b->v0 : b->u0, to = family == 0 ? b->v1 : b->u1;
      sides.push_back(
          {family, rank, from, to, rank == (family == 0 ? b->u0 : b->v0), c, lines[m], across});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return std::tie(a.family, a.rank, a.starts, a.polygon) <
           std::tie(b.family, b.rank, b.starts, b.polygon);
  });
  for (std::size_t first = 0, last = 0; first < sides.size(); first = last) {
    for (last = first; last < sides.size() && sides[last].family == sides[first].family &&
                       sides[last].rank == sides[first].rank;)
      ++last;
    for (std::size_t e = first; e < last && !sides[e].starts; ++e)
      for (std::size_t s = e + 1; s < last; ++s) {
        const Side &ends = sides[e], &starts = sides[s];
        if (!starts.starts || starts.to <= ends.from || ends.to <= starts.from) continue;
        const Contribution &a = contributions[ends.polygon], &b = contributions[starts.polygon];
        for (const bool below : {true, false})
          if ((below ? a.below && b.below : a.above && b.above) &&
              wedges_apart(set, plane, ends.line, starts.line, ends.across, below))
            return true;
      }
  }
  return false;
}

// The windows: around each slanted edge the cells its ends may reach, and windows that share a
// cell merged into their box until none do. Outside them a slanted polygon holds a cell whole
// or not at all (its other edges run along grid lines from grid point to grid point).
void find_windows(PlaneGrid& pg, const std::vector<Contribution>& contributions, Layout& layout) {
  std::vector<Block>& windows = layout.windows;
  for (const std::size_t c : layout.slanted) {
    const std::vector<XPoint>& corners = contributions[c].polygon.vertices;
    layout.reach.push_back(reach(pg, corners));
    const std::size_t n = corners.size();
    for (std::size_t m = 0; m < n; ++m)
      if (layout.kinds[c][m] < 0)
        windows.push_back(reach(pg, std::array{corners[(m + n - 1) % n], corners[m]}));
  }
  for (std::size_t a = 0; a < windows.size();) {
    const auto b = std::find_if(windows.begin() + std::ptrdiff_t(a) + 1, windows.end(),
                                [&](const Block& w) { return share_a_cell(windows[a], w); });
    if (b == windows.end()) {
      ++a;
      continue;
    }
    windows[a] = {std::min(windows[a].u0, b->u0), std::max(windows[a].u1, b->u1),
                  std::min(windows[a].v0, b->v0), std::max(windows[a].v1, b->v1)};
    windows.erase(b);
    a = 0;  // the grown window may now share cells with one looked at before
  }
  const Grid& g = pg.grid();
  layout.in_window.assign(pg.cells(), 0);
  for (const Block& w : windows)
    for (std::uint32_t v = w.v0; v < w.v1; ++v)
      for (std::uint32_t u = w.u0; u < w.u1; ++u) layout.in_window[g.cell(u, v)] = 1;
}

// The cells outside the windows that each slanted polygon holds whole. @return false where it
// holds one in part (not expected) or that would look at more than kMaxGridCells cells in all.
bool find_holds(PlaneGrid& pg, const std::vector<Contribution>& contributions, Layout& layout,
                std::size_t& work) {
  const Grid& g = pg.grid();
  for (std::size_t s = 0; s < layout.slanted.size(); ++s) {
    const Block& b = layout.reach[s];
    work += std::size_t(b.u1 - b.u0) * (b.v1 - b.v0);
    if (work > kMaxGridCells) return false;
    for (std::uint32_t v = b.v0; v < b.v1; ++v)
      for (std::uint32_t u = b.u0; u < b.u1; ++u) {
        if (layout.in_window[g.cell(u, v)]) continue;
        const Cover cover = cover_of(pg, contributions[layout.slanted[s]].polygon, u, v);
        if (cover == Cover::part) return false;
        if (cover == Cover::inside) layout.holds.emplace_back(g.cell(u, v), layout.slanted[s]);
      }
  }
  return true;
}

// The polygons the windows' general boolean takes: each rectangle and slanted polygon meeting a
// window, clipped to it.
std::size_t window_pieces(const Layout& layout) {
  std::size_t n = 0;
  for (const Block& w : layout.windows) {
    for (const auto& b : layout.block_of) n += b && share_a_cell(*b, w);
    for (const Block& r : layout.reach) n += share_a_cell(r, w);
  }
  return n;
}

// Each cell's owners from the polygons holding it whole (none in a window).
void find_owners(PlaneGrid& pg, const std::vector<Contribution>& contributions,
                 const Layout& layout) {
  Grid& g = pg.grid();
  std::vector<Presence> presence(pg.cells());
  for (std::size_t c = 0; c < contributions.size(); ++c)
    if (const auto& b = layout.block_of[c])
      for (std::uint32_t v = b->v0; v < b->v1; ++v)
        for (std::uint32_t u = b->u0; u < b->u1; ++u) presence[g.cell(u, v)].add(contributions[c]);
  for (const auto& [cell, c] : layout.holds) presence[cell].add(contributions[c]);
  g.owners.clear();
  g.owners.reserve(presence.size());
  for (std::size_t cell = 0; cell < presence.size(); ++cell)
    g.owners.push_back(layout.in_window[cell] ? FaceOwners{} : presence[cell].owners());
}

// Where a face's edge is split besides its corners: where a rectangle's edge passes or ends,
// and at the windows' corners (the general boolean's faces there have vertices).
void mark_split_points(Grid& g, const Layout& layout) {
  g.on_u_line.assign(g.nu * g.nv, 0);
  g.on_v_line.assign(g.nu * g.nv, 0);
  for (const auto& b : layout.block_of) {
    if (!b) continue;
    for (std::uint32_t v = b->v0; v <= b->v1; ++v)
      g.on_u_line[g.point(b->u0, v)] = g.on_u_line[g.point(b->u1, v)] = 1;
    for (std::uint32_t u = b->u0; u <= b->u1; ++u)
      g.on_v_line[g.point(u, b->v0)] = g.on_v_line[g.point(u, b->v1)] = 1;
  }
  for (const Block& w : layout.windows)
    for (const std::uint32_t p :
         {g.point(w.u0, w.v0), g.point(w.u1, w.v0), g.point(w.u0, w.v1), g.point(w.u1, w.v1)})
      g.on_u_line[p] = g.on_v_line[p] = 1;
}

// The faces of the regions' loops, into `faces`. @return false if a region cannot be traced.
bool trace_faces(PlaneGrid& pg, PlaneRef plane, int view_side, std::vector<SolidFace>& faces) {
  const Grid& g = pg.grid();
  TraceScratch scratch{std::vector<std::uint32_t>(g.nu * g.nv, UINT32_MAX),
                       std::vector<char>(g.nu * g.nv, 0)};
  for (const Region& r : find_regions(g)) {
    const auto loops = region_loops(g, r, scratch);
    if (!loops) return false;
    for (const std::vector<Step>& loop : *loops) {
      std::vector<std::uint32_t> corners = face_corners(g, loop);
      if (view_side * r.side < 0) std::reverse(corners.begin(), corners.end());
      SolidFace face{{plane.id, r.side}, std::size_t(r.owner), {}, {}, {}};
      face.vertices.reserve(corners.size());
      face.lines.reserve(corners.size());
      face.rounded.reserve(corners.size());
      for (std::size_t m = 0; m < corners.size(); ++m) {
        const std::uint32_t p = corners[m], q = corners[(m + 1) % corners.size()];
        const std::size_t at = pg.corner(g.u_of(p), g.v_of(p));
        face.vertices.push_back(pg.points()[at]);
        face.rounded.push_back(pg.points().round(at));
        face.lines.push_back(g.v_of(p) == g.v_of(q) ? PlaneRef{pg.vs().line(g.v_of(p)), 1}
                                                    : PlaneRef{pg.us().line(g.u_of(p)), 1});
      }
      faces.push_back(std::move(face));
    }
  }
  return true;
}

// The faces in the windows: one general boolean of every polygon meeting a window, clipped to
// it, into `faces`. @return false where a face has a hole (it would need cuts: the whole plane
// goes to the general boolean then).
bool window_faces(PlaneGrid& pg, const PlaneSet& set, PlaneRef plane, int view_side,
                  const std::vector<Contribution>& contributions, const Layout& layout,
                  std::vector<SolidFace>& faces) {
  std::vector<Contribution> pieces;
  const auto piece = [&](PlanePolygon polygon, const Contribution& c) {
    pieces.push_back({std::move(polygon), c.primitive, c.solid, c.above, c.below});
  };
  for (const Block& w : layout.windows) {
    for (std::size_t c = 0; c < contributions.size(); ++c)
      if (const auto& b = layout.block_of[c]; b && share_a_cell(*b, w))
        piece(block_polygon(pg, plane, view_side,
                            {std::max(b->u0, w.u0), std::min(b->u1, w.u1), std::max(b->v0, w.v0),
                             std::min(b->v1, w.v1)}),
              contributions[c]);
    const PlanePolygon window = block_polygon(pg, plane, view_side, w);
    for (std::size_t s = 0; s < layout.slanted.size(); ++s) {
      if (!share_a_cell(layout.reach[s], w)) continue;
      const Contribution& c = contributions[layout.slanted[s]];
      PlanePolygon clipped = c.polygon;
      if (std::all_of(window.lines.begin(), window.lines.end(),
                      [&](PlaneRef t) { return clip_polygon(set, clipped, t); }))
        piece(std::move(clipped), c);
    }
  }
  if (pieces.empty()) return true;
  PlaneFaces rest = PlaneBoolean(set, plane, std::move(pieces)).faces();
  if (!rest.holes.empty()) return false;
  for (SolidFace& f : rest.faces) faces.push_back(std::move(f));
  return true;
}

}  // namespace

std::optional<std::vector<SolidFace>> grid_faces(const PlaneSet& set, PlaneRef plane,
                                                 const std::vector<Contribution>& contributions) {
  const IntervalScope intervals;
  // The plane's view (convex_pieces.h) drops its dominant axis k: u and v are its axes i, j.
  const int k = dominant_axis(set, plane.id), i = (k + 1) % 3, j = (k + 2) % 3;
  Layout layout;
  std::array<std::vector<PlaneId>, 2> lines =
      classify_lines(set, plane, i, j, contributions, layout);
  // The cells are counted before the grid lays out its points: lines of one trace share a rank,
  // so there are at most as many ranks as lines.
  if (2 * layout.slanted.size() > contributions.size() || lines[0].size() < 2 ||
      lines[1].size() < 2 || (lines[0].size() - 1) * (lines[1].size() - 1) > kMaxGridCells)
    return std::nullopt;
  PlaneGrid pg(set, plane, k, std::move(lines));
  if (!slanted_within(pg, contributions, layout)) return std::nullopt;
  std::size_t work = 0;
  if (!find_blocks(pg, contributions, layout, work) || work > kMaxGridCells ||
      may_be_pinched(pg, set, plane, contributions, layout))
    return std::nullopt;
  find_windows(pg, contributions, layout);
  // The windows' polygons go through the general boolean: worth it while they are fewer than
  // the plane's.
  if (window_pieces(layout) > contributions.size() || !find_holds(pg, contributions, layout, work))
    return std::nullopt;
  find_owners(pg, contributions, layout);
  mark_split_points(pg.grid(), layout);
  // Counter-clockwise in the grid is counter-clockwise in the view, seen from +e_k: seen from
  // outside where the face looks to the side of e_k.
  const int view_side = coefficient_sign(set, plane.id, k);
  std::vector<SolidFace> faces;
  if (!trace_faces(pg, plane, view_side, faces) ||
      !window_faces(pg, set, plane, view_side, contributions, layout, faces))
    return std::nullopt;
  return faces;
}

}  // namespace roomcad::detail
