// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/grid_tracing.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

#include "core/flat_index.h"

namespace roomcad::detail::grid {
namespace {

// The region's boundary: unit steps with its cells on their left, each cell's sides that no
// cell of the region shares (its cells only: a region's box may span most of the grid). A cut
// (per line of constant v) parts the cells on its two sides as if one of them were not the
// region's.
std::vector<Step> boundary(const Grid& g, const Region& r, const std::vector<char>& cut) {
  const auto in = [&](std::uint32_t u, std::uint32_t v) {
    return u >= r.u0 && u < r.u1 && v >= r.v0 && v < r.v1 &&
           g.owner(g.cell(u, v), r.side) == r.owner;
  };
  const auto parted = [&](std::uint32_t v) { return !cut.empty() && cut[v]; };
  std::vector<Step> steps;
  for (const std::uint32_t cell : r.cells) {
    const auto u = std::uint32_t(cell % (g.nu - 1)), v = std::uint32_t(cell / (g.nu - 1));
    if (v == 0 || !in(u, v - 1) || parted(v)) steps.push_back({g.point(u, v), east});
    if (!in(u, v + 1) || parted(v + 1)) steps.push_back({g.point(u + 1, v + 1), west});
    if (u == 0 || !in(u - 1, v)) steps.push_back({g.point(u, v + 1), south});
    if (!in(u + 1, v)) steps.push_back({g.point(u + 1, v), north});
  }
  return steps;
}

// Links the steps into closed loops: at a point where two of them start (the region's cells
// touch there at a corner only, or a cut parts them), the left turn first, then straight on,
// so each loop keeps to cells joined by edges. Each loop starts at its least step (by point,
// then direction), and the loops come in the order of those, whatever the steps' order. None
// if a loop does not close (never expected: the region's boundary has as many steps into a
// point as out of it). O(s) for s steps, and the loops' sort.
// @param[in,out] starts  per grid point, kNone (scratch, left so)
std::optional<std::vector<std::vector<Step>>> link(const Grid& g, const std::vector<Step>& steps,
                                                   std::vector<std::uint32_t>& starts) {
  constexpr std::uint32_t kNone = UINT32_MAX;
  std::vector<std::uint32_t> also(steps.size());  // per step, the next step from its point
  for (std::size_t i = 0; i < steps.size(); ++i) {
    also[i] = starts[steps[i].from];
    starts[steps[i].from] = std::uint32_t(i);
  }
  // 0: a left turn, 1: straight on, 2: a right turn, 3: back.
  const auto preference = [](const Step& in, const Step& out) {
    return (in.dir - out.dir + 5) % 4;
  };
  std::vector<std::uint32_t> successor(steps.size(), kNone);
  for (std::size_t i = 0; i < steps.size(); ++i)
    for (std::uint32_t c = starts[g.end(steps[i])]; c != kNone; c = also[c])
      if (successor[i] == kNone ||
          preference(steps[i], steps[c]) < preference(steps[i], steps[successor[i]]))
        successor[i] = c;
  for (const Step& s : steps) starts[s.from] = kNone;
  const auto less = [](const Step& a, const Step& b) {
    return a.from < b.from || (a.from == b.from && a.dir < b.dir);
  };
  std::vector<char> used(steps.size(), 0);
  std::vector<std::vector<Step>> loops;
  for (std::size_t start = 0; start < steps.size(); ++start) {
    if (used[start]) continue;
    std::vector<Step>& loop = loops.emplace_back();
    std::size_t at = start;
    do {
      if (successor[at] == kNone) return std::nullopt;
      used[at] = 1;
      loop.push_back(steps[at]);
      at = successor[at];
    } while (!used[at]);
    if (at != start) return std::nullopt;
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end(), less), loop.end());
  }
  std::sort(loops.begin(), loops.end(),
            [&](const auto& a, const auto& b) { return less(a.front(), b.front()); });
  return loops;
}

// Splits a loop that passes a point twice (the region touches itself at a corner there) into
// loops that pass each point once.
// @param[in,out] marked  per grid point, 0 (scratch, left so)
void split_at_repeats(std::vector<Step> loop, std::vector<char>& marked,
                      std::vector<std::vector<Step>>& out) {
  bool repeats = false;
  for (const Step& s : loop) {
    repeats = repeats || marked[s.from];
    marked[s.from] = 1;
  }
  for (const Step& s : loop) marked[s.from] = 0;
  if (!repeats) {
    out.push_back(std::move(loop));
    return;
  }
  // Walking the loop, a point seen before closes the part of the loop since then.
  std::vector<Step> open;
  FlatIndex<std::uint64_t> seen(loop.size());
  std::vector<std::uint32_t> position;  // per index in `seen`: where in `open` (kNone: closed)
  for (const Step& s : loop) {
    const auto [k, added] = seen.try_emplace(s.from, std::uint32_t(position.size()));
    if (added) {
      position.push_back(std::uint32_t(open.size()));
    } else if (position[k] != FlatIndex<std::uint64_t>::kNone) {
      const std::size_t from = position[k];
      for (std::size_t m = from; m < open.size(); ++m)
        position[seen.find(open[m].from)] = FlatIndex<std::uint64_t>::kNone;
      out.emplace_back(open.begin() + std::ptrdiff_t(from), open.end());
      open.resize(from);
      position[k] = std::uint32_t(open.size());
    } else {
      position[k] = std::uint32_t(open.size());
    }
    open.push_back(s);
  }
  out.push_back(std::move(open));
}

// Twice the loop's signed area in grid units: > 0 counter-clockwise (an outer boundary), < 0 a
// hole.
std::int64_t twice_area(const Grid& g, const std::vector<Step>& loop) {
  std::int64_t sum = 0;
  for (const Step& s : loop) {
    const std::uint32_t to = g.end(s);
    sum += std::int64_t(g.u_of(s.from)) * g.v_of(to) - std::int64_t(g.u_of(to)) * g.v_of(s.from);
  }
  return sum;
}

}  // namespace

// The regions, in the order PlaneBoolean files its face groups: side, then owner.
std::vector<Region> find_regions(const Grid& g) {
  std::vector<Region> regions;
  FlatIndex<std::uint64_t> region_of;
  // Neighbouring cells mostly have the same owners: the last lookup of each side is kept.
  std::array<std::pair<long, std::uint32_t>, 2> last{{{-1, 0}, {-1, 0}}};
  for (std::uint32_t v = 0; v + 1 < g.nv; ++v)
    for (std::uint32_t u = 0; u + 1 < g.nu; ++u)
      for (const int side : {-1, 1}) {
        const long owner = g.owner(g.cell(u, v), side);
        if (owner < 0) continue;
        auto& [last_owner, r] = last[side > 0 ? 1 : 0];
        if (owner != last_owner) {
          const auto [at, added] = region_of.try_emplace(
              (std::uint64_t(owner) << 1) | (side > 0 ? 1u : 0u), std::uint32_t(regions.size()));
          if (added) regions.push_back({side, owner, u, u + 1, v, v + 1, {}});
          last_owner = owner, r = at;
        }
        Region& region = regions[r];
        region.u0 = std::min(region.u0, u), region.u1 = std::max(region.u1, u + 1);
        region.v1 = v + 1;  // cells come in order of v
        region.cells.push_back(std::uint32_t(g.cell(u, v)));
      }
  std::sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) {
    return std::tie(a.side, a.owner) < std::tie(b.side, b.owner);
  });
  return regions;
}

// The region's loops, each passing a point once; where some are holes, the region is cut along
// the line of constant v through each hole's top and traced again. None if holes remain.
std::optional<std::vector<std::vector<Step>>> region_loops(const Grid& g, const Region& r,
                                                           TraceScratch& scratch) {
  std::vector<char> cut;
  for (int round = 0; round < 2; ++round) {
    auto linked = link(g, boundary(g, r, cut), scratch.starts);
    if (!linked) return std::nullopt;
    std::vector<std::vector<Step>> loops;
    for (std::vector<Step>& loop : *linked)
      split_at_repeats(std::move(loop), scratch.marked, loops);
    std::vector<std::uint32_t> tops;
    for (const std::vector<Step>& loop : loops) {
      if (twice_area(g, loop) > 0) continue;
      std::uint32_t top = 0;
      for (const Step& s : loop) top = std::max(top, g.v_of(s.from));
      tops.push_back(top);
    }
    if (tops.empty()) return loops;
    cut.assign(g.nv, 0);
    for (const std::uint32_t z : tops) cut[z] = 1;
  }
  return std::nullopt;
}

// The grid points of a face: the loop's corners and the points where another polygon's edge
// crosses or ends on it, counter-clockwise in the grid (u, v).
std::vector<std::uint32_t> face_corners(const Grid& g, const std::vector<Step>& loop) {
  const std::size_t n = loop.size();
  std::vector<std::uint32_t> corners;
  for (std::size_t m = 0; m < n; ++m) {
    const Step& s = loop[m];
    const bool along_u = s.dir == east || s.dir == west;  // on a line of constant v
    if (s.dir != loop[(m + n - 1) % n].dir || (along_u ? g.on_u_line[s.from] : g.on_v_line[s.from]))
      corners.push_back(s.from);
  }
  return corners;
}

}  // namespace roomcad::detail::grid
