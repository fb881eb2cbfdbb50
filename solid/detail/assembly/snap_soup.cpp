// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/assembly/snap_soup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

#include "core/flat_index.h"
#include "geometry/exact_wall_lines.h"

namespace roomcad::detail {
namespace {

using Polygon = std::vector<std::size_t>;

// For each point, the point whose coordinates it takes: groups of points within `tolerance`
// of each other (transitively), never joining two groups that each hold an exact point; a
// group's root is its exact point, else its lowest index. Points hash into cubes, so near
// points are in the same or adjacent cubes.
std::vector<std::size_t> find_snap_targets(const std::vector<OpenMesh::Vec3d>& points,
                                           const std::function<bool(std::size_t)>& exact,
                                           double tolerance) {
  std::vector<std::size_t> parent(points.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto is_exact = [&](std::size_t root) { return exact && exact(root); };
  auto unite = [&](std::size_t a, std::size_t b) {
    if (a == b || (is_exact(a) && is_exact(b))) return;
    const bool a_root = is_exact(a) || (!is_exact(b) && a < b);
    if (a_root) parent[b] = a;
    else parent[a] = b;
  };
  // Cells of 64 tolerances, no smaller than an ulp of the largest coordinate (so that every
  // cell index fits an int64 whatever the tolerance): a point's near neighbours lie in its
  // own cell, or in the next one along an axis where it lies within the tolerance of that
  // side (2 tolerances, for the rounding of the division: a larger reach only adds
  // candidates). So most points look in one cell, not 27, and every candidate is met in the
  // same order as over all 27.
  double largest = 0.0;
  for (const OpenMesh::Vec3d& p : points)
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(p[k]));
  const double cell = std::max({64.0 * tolerance, largest * 0x1p-52, 1e-300});
  // Per cell (numbered in order of first point), its points in order of index: the first and
  // the last, each linked to the next.
  constexpr std::size_t kNone = SIZE_MAX;
  using CellKey = std::array<std::uint64_t, 3>;
  FlatIndex<CellKey> cells(points.size());
  std::vector<std::pair<std::size_t, std::size_t>> ends;
  std::vector<std::size_t> next(points.size(), kNone);
  auto index = [&](double v) { return std::int64_t(std::floor(v / cell)); };
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return CellKey{std::uint64_t(x), std::uint64_t(y), std::uint64_t(z)};
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::array<std::int64_t, 3> c, low, high;
    for (std::size_t k = 0; k < 3; ++k) {
      c[k] = index(points[i][int(k)]);
      low[k] = index(points[i][int(k)] - 2.0 * tolerance) - c[k];
      high[k] = index(points[i][int(k)] + 2.0 * tolerance) - c[k];
    }
    for (std::int64_t dx = low[0]; dx <= high[0]; ++dx)
      for (std::int64_t dy = low[1]; dy <= high[1]; ++dy)
        for (std::int64_t dz = low[2]; dz <= high[2]; ++dz) {
          const std::uint32_t at = cells.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (at == FlatIndex<CellKey>::kNone) continue;
          for (std::size_t j = ends[at].first; j != kNone; j = next[j]) {
            const OpenMesh::Vec3d d = points[i] - points[j];
            if (std::abs(d[0]) > tolerance || std::abs(d[1]) > tolerance ||
                std::abs(d[2]) > tolerance)
              continue;
            unite(find(i), find(j));
          }
        }
    const auto [at, fresh] = cells.try_emplace(key(c[0], c[1], c[2]), std::uint32_t(ends.size()));
    if (fresh) ends.emplace_back(i, i);
    else next[ends[at].second] = i, ends[at].second = i;
  }
  for (std::size_t i = 0; i < points.size(); ++i) parent[i] = find(i);
  return parent;
}

// Drops repeated neighbours (cyclically) and spikes a, b, a, until neither is left. O(n^2).
void drop_repeats_and_spikes(Polygon& p) {
  for (bool changed = true; changed && !p.empty();) {
    changed = false;
    p.erase(std::unique(p.begin(), p.end()), p.end());
    while (p.size() > 1 && p.back() == p.front()) p.pop_back();
    const std::size_t n = p.size();
    for (std::size_t k = 0; n >= 3 && k < n; ++k)
      if (p[(k + n - 1) % n] == p[(k + 1) % n]) {
        // Remove the spike's tip and one copy of its base; the other copy stays.
        const std::size_t tip = k, base = (k + 1) % n;
        p.erase(p.begin() + std::ptrdiff_t(std::max(tip, base)));
        p.erase(p.begin() + std::ptrdiff_t(std::min(tip, base)));
        changed = true;
        break;
      }
  }
}

// Appends the polygon, cleaned, to `out` (and its tag to `tags`): split where it touches
// itself at a corner.
void append_clean(Polygon p, std::size_t tag, std::vector<Polygon>& out,
                  std::vector<std::size_t>& tags) {
  drop_repeats_and_spikes(p);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (p[i] != p[j]) continue;
      Polygon first(p.begin() + std::ptrdiff_t(i), p.begin() + std::ptrdiff_t(j));
      Polygon second(p.begin() + std::ptrdiff_t(j), p.end());
      second.insert(second.end(), p.begin(), p.begin() + std::ptrdiff_t(i));
      append_clean(std::move(first), tag, out, tags);
      append_clean(std::move(second), tag, out, tags);
      return;
    }
  if (p.size() < 3) return;
  out.push_back(std::move(p));
  tags.push_back(tag);
}

// The polygon's cycle starting at its lowest index (same orientation).
Polygon canonical(const Polygon& p) {
  Polygon c(p);
  std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  return c;
}

// Removes both polygons (and their tags) of every pair that are one another's reverse. Only
// polygons with the same corners can pair, so cycles are compared only within groups of one
// corner hash (the same for a polygon and its reverse), each in order. O(n log n).
void drop_fins(std::vector<Polygon>& polygons, std::vector<std::size_t>& tags) {
  std::vector<std::pair<std::uint64_t, std::size_t>> by_corners;  // (corner hash, polygon)
  by_corners.reserve(polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    std::uint64_t hash = polygons[k].size();
    for (const std::size_t i : polygons[k]) hash += mix_bits(i);
    by_corners.emplace_back(hash, k);
  }
  std::sort(by_corners.begin(), by_corners.end());
  std::vector<char> gone(polygons.size(), 0);
  for (auto group = by_corners.begin(); group != by_corners.end();) {
    const auto end = std::find_if(group, by_corners.end(),
                                  [&](const auto& e) { return e.first != group->first; });
    std::map<Polygon, std::vector<std::size_t>> open;  // cycle -> unmatched polygons with it
    for (auto it = group; it != end && end - group > 1; ++it) {
      const std::size_t k = it->second;
      const Polygon reversed = canonical(Polygon(polygons[k].rbegin(), polygons[k].rend()));
      const auto match = open.find(reversed);
      if (match != open.end() && !match->second.empty()) {
        gone[k] = gone[match->second.back()] = 1;
        match->second.pop_back();
        continue;
      }
      open[canonical(polygons[k])].push_back(k);
    }
    group = end;
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < polygons.size(); ++k)
    if (!gone[k]) {
      if (kept != k) polygons[kept] = std::move(polygons[k]), tags[kept] = tags[k];
      ++kept;
    }
  polygons.resize(kept);
  tags.resize(kept);
}

// Whether a, b, c lie on one line, exactly for the doubles given.
bool are_collinear(const OpenMesh::Vec3d& a, const OpenMesh::Vec3d& b, const OpenMesh::Vec3d& c) {
  return exact::decide([&](auto tag) -> bool {
    using NT = decltype(tag);
    const NT ux = NT(b[0]) - NT(a[0]), uy = NT(b[1]) - NT(a[1]), uz = NT(b[2]) - NT(a[2]);
    const NT vx = NT(c[0]) - NT(a[0]), vy = NT(c[1]) - NT(a[1]), vz = NT(c[2]) - NT(a[2]);
    return uy * vz - uz * vy == NT(0) && uz * vx - ux * vz == NT(0) && ux * vy - uy * vx == NT(0);
  });
}

// Whether every corner of the polygon lies on the line of its first two: no area at all.
bool is_flat(const std::vector<OpenMesh::Vec3d>& points, const Polygon& p) {
  for (std::size_t k = 2; k < p.size(); ++k)
    if (!are_collinear(points[p[0]], points[p[1]], points[p[k]])) return false;
  return true;
}

// The flat polygon's corners in order along its line: by the coordinate that varies most
// (on an exact line every coordinate is monotone along it, and that one strictly).
Polygon corners_along_line(const std::vector<OpenMesh::Vec3d>& points, const Polygon& flat) {
  Polygon corners(flat);
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  int axis = 0;
  double widest = -1.0;
  for (int k = 0; k < 3; ++k) {
    const auto [lo, hi] = std::minmax_element(
        corners.begin(), corners.end(),
        [&](std::size_t a, std::size_t b) { return points[a][k] < points[b][k]; });
    if (points[*hi][k] - points[*lo][k] > widest)
      widest = points[*hi][k] - points[*lo][k], axis = k;
  }
  std::sort(corners.begin(), corners.end(),
            [&](std::size_t a, std::size_t b) { return points[a][axis] < points[b][axis]; });
  return corners;
}

// Removes the polygons with no area (rounding flattened a sliver's side to a segment: every
// corner on one line) and keeps the surface closed: each edge of another polygon that runs
// between two corners of a removed one gets the removed one's corners between them, so the
// edges that met the flat polygon from both sides now meet each other. O(n) for n corners
// when no polygon is flat.
void collapse_flat_polygons(const std::vector<OpenMesh::Vec3d>& points,
                            std::vector<Polygon>& polygons, std::vector<std::size_t>& tags) {
  std::vector<char> flat(polygons.size(), 0);
  std::vector<Polygon> lines;  // per flat polygon, its corners along its line
  for (std::size_t k = 0; k < polygons.size(); ++k)
    if (is_flat(points, polygons[k])) {
      flat[k] = 1;
      lines.push_back(corners_along_line(points, polygons[k]));
    }
  if (lines.empty()) return;
  std::unordered_map<std::size_t, std::vector<std::size_t>> lines_at;  // corner -> lines through it
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (const std::size_t c : lines[l]) lines_at[c].push_back(l);
  std::vector<Polygon> kept;
  std::vector<std::size_t> kept_tags;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    if (flat[k]) continue;
    const Polygon& p = polygons[k];
    Polygon split;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t a = p[i], b = p[(i + 1) % p.size()];
      split.push_back(a);
      const auto at_a = lines_at.find(a);
      if (at_a == lines_at.end()) continue;
      for (const std::size_t l : at_a->second) {
        const Polygon& line = lines[l];
        const auto ia = std::find(line.begin(), line.end(), a),
                   ib = std::find(line.begin(), line.end(), b);
        if (ib == line.end()) continue;
        if (ia < ib) split.insert(split.end(), ia + 1, ib);
        else
          split.insert(split.end(), std::make_reverse_iterator(ia),
                       std::make_reverse_iterator(ib + 1));
        break;
      }
    }
    kept.push_back(std::move(split));
    kept_tags.push_back(tags[k]);
  }
  polygons = std::move(kept);
  tags = std::move(kept_tags);
}

// Moves every corner to its snap target (find_snap_targets) and cleans the polygons.
IndexedSoup snap_to(IndexedSoup soup, const std::vector<std::size_t>& target) {
  const bool tagged = !soup.tags.empty();
  std::vector<Polygon> cleaned;
  std::vector<std::size_t> tags;
  cleaned.reserve(soup.polygons.size());
  for (std::size_t k = 0; k < soup.polygons.size(); ++k) {
    Polygon& p = soup.polygons[k];
    for (std::size_t& i : p) i = target[i];
    append_clean(std::move(p), tagged ? soup.tags[k] : 0, cleaned, tags);
  }
  collapse_flat_polygons(soup.points, cleaned, tags);
  drop_fins(cleaned, tags);
  soup.polygons = std::move(cleaned);
  if (tagged) soup.tags = std::move(tags);
  return soup;
}

// Whether every edge of the polygons is used exactly once each way: a closed surface whose
// edges each join two faces. O(n) expected for n corners.
bool has_paired_edges(const std::vector<Polygon>& polygons) {
  struct EdgeHash {
    std::size_t operator()(const std::pair<std::size_t, std::size_t>& e) const {
      return std::hash<std::size_t>()(e.first * 0x9E3779B97F4A7C15ull ^ e.second);
    }
  };
  std::unordered_map<std::pair<std::size_t, std::size_t>, int, EdgeHash> uses;
  for (const Polygon& p : polygons)
    for (std::size_t k = 0; k < p.size(); ++k) ++uses[{p[k], p[(k + 1) % p.size()]}];
  for (const auto& [edge, n] : uses) {
    const auto twin = uses.find({edge.second, edge.first});
    if (n != 1 || twin == uses.end() || twin->second != 1) return false;
  }
  return true;
}

// Whether snapping to `target` puts two exact points (`exact`, possibly empty) in one group.
// Asks `exact` only of points in groups of two or more.
bool merges_exact_points(const std::vector<std::size_t>& target,
                         const std::function<bool(std::size_t)>& exact) {
  if (!exact) return false;
  std::vector<std::size_t> group_size(target.size(), 0);
  for (const std::size_t t : target) ++group_size[t];
  std::vector<char> holds_exact(target.size(), 0);
  for (std::size_t i = 0; i < target.size(); ++i) {
    if (group_size[target[i]] < 2 || !exact(i)) continue;
    if (holds_exact[target[i]]) return true;
    holds_exact[target[i]] = 1;
  }
  return false;
}

}  // namespace

IndexedSoup snap_soup(IndexedSoup soup, double tolerance) {
  const std::vector<std::size_t> merging = find_snap_targets(soup.points, nullptr, tolerance);
  // Keeping exact corners apart changes nothing unless two of them would merge (rare): only
  // then is the result checked and, where it must be, the soup snapped again.
  if (!merges_exact_points(merging, soup.is_exact)) return snap_to(std::move(soup), merging);
  IndexedSoup merged = snap_to(soup, merging);
  if (has_paired_edges(merged.polygons)) return merged;
  // Merging two exact corners pinched the surface (walls an ulp apart, each corner exact:
  // an edge of four faces). Keeping exact corners apart leaves them as the exact solid has
  // them; taken only where that closes the surface.
  const std::vector<std::size_t> apart_targets =
      find_snap_targets(soup.points, soup.is_exact, tolerance);
  IndexedSoup apart = snap_to(std::move(soup), apart_targets);
  return has_paired_edges(apart.polygons) ? apart : merged;
}

double snap_tolerance(const std::vector<OpenMesh::Vec3d>& points) {
  double largest = 0.0;
  for (const OpenMesh::Vec3d& p : points)
    largest = std::max({largest, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  if (largest == 0.0) return 0.0;
  return 4.0 * (std::nextafter(largest, std::numeric_limits<double>::infinity()) - largest);
}

}  // namespace roomcad::detail
