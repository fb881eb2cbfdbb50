// SPDX-License-Identifier: GPL-3.0-or-later
// Triangles of one plane joined by shared edges: what Makarov & Safin call one face (the scene
// holds the model's polygons as triangles), so a region seeing only that plane can stop early.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "render/detail/visibility_split.h"

namespace roomcad::detail {
namespace {

/// An edge by its corners in canonical order, and where it comes from.
struct EdgeRef {
  double ax, ay, bx, by;
  std::uint32_t triangle;
  int edge;
  [[nodiscard]] auto key() const { return std::tie(ax, ay, bx, by); }
};

EdgeRef make_edge(const FlatTriangle& t, std::uint32_t index, int i) {
  Point2 a = t.p[i], b = t.p[(i + 1) % 3];
  if (std::tie(b.x, b.y) < std::tie(a.x, a.y)) std::swap(a, b);
  return {a.x, a.y, b.x, b.y, index, i};
}

/// The planes come from the rasteriser's float corner depths (2^-24 relative each), which a
/// small triangle's plane magnifies at its neighbour's corners: 1e-6 split true planes apart
/// (house: twice the regions). Grouping only decides where splitting stops; every sample is
/// still decided exactly.
bool is_same_plane(const FlatTriangle& s, const FlatTriangle& t) {
  for (const Point2& p : t.p) {
    const double a = s.depth_at(p.x, p.y), b = t.depth_at(p.x, p.y);
    if (std::abs(a - b) > 1e-5 * std::max(std::abs(a), std::abs(b))) return false;
  }
  return true;
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

void group_coplanar(std::vector<FlatTriangle>& triangles) {
  std::vector<EdgeRef> edges;
  edges.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) edges.push_back(make_edge(triangles[t], t, i));
  std::sort(edges.begin(), edges.end(), [](const EdgeRef& a, const EdgeRef& b) {
    return std::tie(a.ax, a.ay, a.bx, a.by, a.triangle, a.edge) <
           std::tie(b.ax, b.ay, b.bx, b.by, b.triangle, b.edge);
  });
  std::vector<std::uint32_t> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
    const EdgeRef &a = edges[k], &b = edges[k + 1];
    const bool pair = a.key() == b.key() &&
                      (k + 2 == edges.size() || edges[k + 2].key() != a.key()) &&
                      (k == 0 || edges[k - 1].key() != a.key());
    if (!pair || !is_same_plane(triangles[a.triangle], triangles[b.triangle])) continue;
    triangles[a.triangle].boundary[a.edge] = false;
    triangles[b.triangle].boundary[b.edge] = false;
    parent[find_root(parent, a.triangle)] = find_root(parent, b.triangle);
  }
  for (std::uint32_t t = 0; t < triangles.size(); ++t) triangles[t].group = find_root(parent, t);
}

}  // namespace roomcad::detail
