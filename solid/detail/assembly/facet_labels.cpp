// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/assembly/facet_labels.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace roomcad::detail {
namespace {

// Faces of an opening are whole polygons of their own; only wall faces can be merged facets.
bool is_mergeable(const SoupFace& f) {
  return f.points.size() == 3 && (f.kind == FaceKind::wall_face || f.kind == FaceKind::wall_top ||
                                  f.kind == FaceKind::wall_bottom || f.kind == FaceKind::wall_end);
}

// Two triangles sharing an edge lie in one plane when their unit normals agree; distinct
// facets meeting at an edge differ by the angle between two walls, far above this.
bool is_coplanar(const OpenMesh::Vec3d& a, const OpenMesh::Vec3d& b) {
  return (a | b) > 1.0 - 1e-9;
}

// Per point, the lowest index of a point with the same coordinates: a triangulated facet's
// corners may come as copies of the facet's vertices.
std::vector<std::size_t> canonical_points(const std::vector<OpenMesh::Vec3d>& points) {
  std::map<std::array<double, 3>, std::size_t> first;
  std::vector<std::size_t> id(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
    id[k] = first.try_emplace({points[k][0], points[k][1], points[k][2]}, k).first->second;
  return id;
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

// Joins mergeable triangles across shared edges where they are coplanar.
std::vector<std::size_t> group_triangles(const IndexedSoup& indexed, const FaceSoup& soup,
                                         const std::vector<OpenMesh::Vec3d>& normals) {
  std::vector<std::size_t> parent(soup.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::unordered_map<std::uint64_t, std::size_t> edge_owner;
  const std::vector<std::size_t> id = canonical_points(indexed.points);
  const auto n = static_cast<std::uint64_t>(indexed.points.size());
  for (std::size_t k = 0; k < soup.size(); ++k) {
    if (!is_mergeable(soup[k])) continue;
    const auto& poly = indexed.polygons[k];
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::uint64_t a = id[poly[i]], b = id[poly[(i + 1) % poly.size()]];
      const auto [it, fresh] = edge_owner.emplace(std::min(a, b) * n + std::max(a, b), k);
      if (!fresh && is_coplanar(normals[k], normals[it->second]))
        parent[find_root(parent, k)] = find_root(parent, it->second);
    }
  }
  for (std::size_t k = 0; k < soup.size(); ++k) parent[k] = find_root(parent, k);
  return parent;
}

using ColourKey = std::tuple<std::uint8_t, std::uint8_t, std::uint8_t>;

ColourKey key_of(const SoupFace& f) { return {f.color.r, f.color.g, f.color.b}; }

}  // namespace

void unify_facet_labels(const IndexedSoup& indexed, FaceSoup& soup) {
  std::vector<OpenMesh::Vec3d> normals(soup.size());
  std::vector<double> areas(soup.size());
  for (std::size_t k = 0; k < soup.size(); ++k) {
    normals[k] = polygon_normal(soup[k].points);
    areas[k] = normals[k].norm();
    if (areas[k] > 0.0) normals[k] /= areas[k];
  }
  const std::vector<std::size_t> root = group_triangles(indexed, soup, normals);
  // Area per colour per group; std::map keeps the choice deterministic on ties.
  std::unordered_map<std::size_t, std::map<ColourKey, std::pair<double, std::size_t>>> votes;
  for (std::size_t k = 0; k < soup.size(); ++k) {
    auto& [area, face] = votes[root[k]].try_emplace(key_of(soup[k]), 0.0, k).first->second;
    area += areas[k];
  }
  std::unordered_map<std::size_t, std::size_t> winner;
  for (const auto& [group, labels] : votes) {
    const auto best = std::max_element(
        labels.begin(), labels.end(),
        [](const auto& x, const auto& y) { return x.second.first < y.second.first; });
    winner[group] = best->second.second;
  }
  for (std::size_t k = 0; k < soup.size(); ++k) {
    const SoupFace& w = soup[winner[root[k]]];
    soup[k].color = w.color;
  }
}

}  // namespace roomcad::detail
