// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/fast_path/fuse_seams.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <unordered_map>

namespace roomcad::detail {
namespace {

struct FaceRef {
  std::size_t soup = 0, face = 0;
  friend bool operator==(const FaceRef&, const FaceRef&) = default;
  friend bool operator<(const FaceRef& a, const FaceRef& b) {
    return a.soup != b.soup ? a.soup < b.soup : a.face < b.face;
  }
};

struct PointHash {
  std::size_t operator()(const OpenMesh::Vec3d& p) const {
    std::size_t h = 0;
    for (int k = 0; k < 3; ++k) {
      std::uint64_t bits;
      std::memcpy(&bits, &p[k], sizeof bits);
      h = h * 0x9e3779b97f4a7c15ULL + bits;
    }
    return h;
  }
};
using FacesAt = std::unordered_map<OpenMesh::Vec3d, std::vector<FaceRef>, PointHash>;

// Index of `p` among the polygon's corners, or its size if absent.
std::size_t find_corner(const std::vector<OpenMesh::Vec3d>& poly, const OpenMesh::Vec3d& p) {
  return static_cast<std::size_t>(std::find(poly.begin(), poly.end(), p) - poly.begin());
}

// Whether two faces may be fused: of one kind, colour and plane, and both of the fast path
// (faces of an indexed soup, from the general or the Nef path, carry their vertex numbers and
// stay as they are).
bool is_alike(const SoupFace& a, const SoupFace& b) {
  const OpenMesh::Vec3d na = polygon_normal(a.points).normalized(),
                        nb = polygon_normal(b.points).normalized();
  return a.kind == b.kind && a.color == b.color && a.copies.empty() && b.copies.empty() &&
         a.vertices.empty() && b.vertices.empty() && (na | nb) > 1.0 - 1e-12;
}

// Removes corner i of the face, with its copy and vertex number where it has them.
void erase_corner(SoupFace& f, std::size_t i) {
  const auto at = static_cast<std::ptrdiff_t>(i);
  f.points.erase(f.points.begin() + at);
  if (!f.copies.empty()) f.copies.erase(f.copies.begin() + at);
  if (!f.vertices.empty()) f.vertices.erase(f.vertices.begin() + at);
}

// Joins polygons p and q across an edge at `at` that p runs one way and q the other.
// @return the fused polygon, or empty if they share no such edge or more than one.
std::vector<OpenMesh::Vec3d> fuse_pair(const std::vector<OpenMesh::Vec3d>& p,
                                       const std::vector<OpenMesh::Vec3d>& q,
                                       const OpenMesh::Vec3d& at) {
  const std::size_t n = p.size(), m = q.size(), ip = find_corner(p, at), iq = find_corner(q, at);
  if (ip == n || iq == m) return {};
  for (const bool at_is_a : {true, false}) {
    // p runs a -> b, q runs b -> a, with `at` being a or b.
    const std::size_t ia = at_is_a ? ip : (ip + n - 1) % n, ib = (ia + 1) % n;
    const std::size_t jb = find_corner(q, p[ib]);
    if (jb == m || q[(jb + 1) % m] != p[ia]) continue;
    std::vector<OpenMesh::Vec3d> out;
    for (std::size_t k = 0; k < n; ++k) out.push_back(p[(ib + k) % n]);
    for (std::size_t k = 2; k < m; ++k) out.push_back(q[(jb + k) % m]);
    std::vector<OpenMesh::Vec3d> sorted = out;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};  // more shared
    return out;
  }
  return {};
}

// Whether the corner at i lies on the straight segment between its neighbours.
bool is_straight_through(const std::vector<OpenMesh::Vec3d>& poly, std::size_t i) {
  const std::size_t n = poly.size();
  if (n < 4 || i == n) return false;
  const OpenMesh::Vec3d a = poly[(i + n - 1) % n], b = poly[(i + 1) % n], d = b - a,
                        e = poly[i] - a;
  const double len = d.norm();
  const double scale = std::max({a.max_abs(), b.max_abs(), 1.0});
  return len > 0.0 && (d | e) > 0.0 && (d | e) < len * len && (d % e).norm() / len <= 1e-12 * scale;
}

void index_faces(std::span<FaceSoup> soups, FacesAt& at) {
  for (std::size_t s = 0; s < soups.size(); ++s)
    for (std::size_t f = 0; f < soups[s].size(); ++f)
      for (const auto& p : soups[s][f].points)
        if (auto it = at.find(p); it != at.end()) it->second.push_back({s, f});
}

SoupFace& face_of(std::span<FaceSoup> soups, FaceRef r) { return soups[r.soup][r.face]; }

// Fuses alike faces around `p` pairwise until none is left to fuse; the absorbed face is
// emptied and every seam point it held now names the survivor.
void fuse_pairs_around(std::span<FaceSoup> soups, const OpenMesh::Vec3d& p, FacesAt& at) {
  for (bool fused = true; fused;) {
    fused = false;
    std::vector<FaceRef>& around = at[p];
    for (std::size_t i = 0; i < around.size() && !fused; ++i)
      for (std::size_t j = i + 1; j < around.size() && !fused; ++j) {
        SoupFace &a = face_of(soups, around[i]), &b = face_of(soups, around[j]);
        if (!is_alike(a, b)) continue;
        std::vector<OpenMesh::Vec3d> joined = fuse_pair(a.points, b.points, p);
        if (joined.empty()) continue;
        const FaceRef keep = around[i], gone = around[j];
        for (const auto& q : b.points)
          if (auto it = at.find(q); it != at.end()) {
            std::replace(it->second.begin(), it->second.end(), gone, keep);
            std::sort(it->second.begin(), it->second.end());
            it->second.erase(std::unique(it->second.begin(), it->second.end()), it->second.end());
          }
        a.points = std::move(joined);
        b.points.clear();
        fused = true;
      }
  }
}

// Whether the triangle (a, p, b) is an ear of `poly` at p: convex there, and no other corner
// of `poly` in it or on its sides.
bool is_ear(const std::vector<OpenMesh::Vec3d>& poly, std::size_t i) {
  const std::size_t n = poly.size();
  const OpenMesh::Vec3d a = poly[(i + n - 1) % n], p = poly[i], b = poly[(i + 1) % n];
  const OpenMesh::Vec3d normal = polygon_normal(poly), turn = (p - a) % (b - p);
  if ((turn | normal) <= 0.0) return false;
  for (const auto& q : poly) {
    if (q == a || q == p || q == b) continue;
    if (((p - a) % (q - a) | turn) >= 0.0 && ((b - p) % (q - p) | turn) >= 0.0 &&
        ((a - b) % (q - b) | turn) >= 0.0)
      return false;
  }
  return true;
}

// Moves the ear at `p` of face f (where p is a corner) into an alike face g that shares one
// of the ear's edges, so that f no longer uses p: the edges at p are the same afterwards, p
// just belongs to fewer faces. @return the corner g gained, if an ear moved.
std::optional<OpenMesh::Vec3d> move_ear(SoupFace& f, SoupFace& g, const OpenMesh::Vec3d& p) {
  auto& poly = f.points;
  const std::size_t n = poly.size(), i = find_corner(poly, p);
  if (n < 4 || i == n || !is_alike(f, g) || !is_ear(poly, i)) return std::nullopt;
  const OpenMesh::Vec3d a = poly[(i + n - 1) % n], b = poly[(i + 1) % n];
  auto& other = g.points;
  const std::size_t m = other.size(), j = find_corner(other, p);
  if (j == m) return std::nullopt;
  OpenMesh::Vec3d gained;
  if (other[(j + m - 1) % m] == b && find_corner(other, a) == m) {
    other.insert(other.begin() + static_cast<std::ptrdiff_t>(j), gained = a);  // g: b, a, p
  } else if (other[(j + 1) % m] == a && find_corner(other, b) == m) {
    other.insert(other.begin() + static_cast<std::ptrdiff_t>(j + 1), gained = b);  // g: p, b, a
  } else {
    return std::nullopt;
  }
  erase_corner(f, i);
  return gained;
}

// Moves one ear at `p` (move_ear) out of a face where p is a corner. @return whether one moved.
bool move_an_ear(std::span<FaceSoup> soups, const OpenMesh::Vec3d& p, FacesAt& at) {
  std::vector<FaceRef>& around = at[p];
  for (std::size_t i = 0; i < around.size(); ++i) {
    SoupFace& f = face_of(soups, around[i]);
    if (is_straight_through(f.points, find_corner(f.points, p))) continue;
    for (std::size_t j = 0; j < around.size(); ++j) {
      if (j == i) continue;
      const auto gained = move_ear(f, face_of(soups, around[j]), p);
      if (!gained) continue;
      if (auto it = at.find(*gained); it != at.end()) {
        it->second.push_back(around[j]);
        std::sort(it->second.begin(), it->second.end());
      }
      around.erase(around.begin() + static_cast<std::ptrdiff_t>(i));
      return true;
    }
  }
  return false;
}

// Fuses the faces around `p` and moves ears out of them until p is straight-through in every
// face, or nothing more changes. Each ear move takes p out of one face, so this ends.
void fuse_around(std::span<FaceSoup> soups, const OpenMesh::Vec3d& p, FacesAt& at) {
  do fuse_pairs_around(soups, p, at);
  while (move_an_ear(soups, p, at));
}

// Drops `p` from the faces around it if it is straight-through in every one of them.
void drop_if_straight(std::span<FaceSoup> soups, const OpenMesh::Vec3d& p, const FacesAt& at) {
  const std::vector<FaceRef>& around = at.at(p);
  for (const FaceRef r : around)
    if (!is_straight_through(face_of(soups, r).points, find_corner(face_of(soups, r).points, p)))
      return;
  for (const FaceRef r : around)
    erase_corner(face_of(soups, r), find_corner(face_of(soups, r).points, p));
}

}  // namespace

std::vector<OpenMesh::Vec3d> find_seam_points(std::span<const Hub> hubs,
                                              const std::vector<WallFrame>& frames) {
  std::vector<OpenMesh::Vec3d> points;
  for (const Hub& h : hubs)
    for (std::size_t k = 0; k < h.arms.size(); ++k) {
      const auto& [wa, ea] = h.arms[k];
      const auto& [wb, eb] = h.arms[(k + 1) % h.arms.size()];
      const Point2 da = outward(frames[wa], ea), db = outward(frames[wb], eb);
      if (da.x * db.x + da.y * db.y > -1.0 + 1e-12) continue;
      for (const double z : {frames[wa].base, frames[wa].top})
        points.emplace_back(h.corners[k].x, h.corners[k].y, z);
    }
  return points;
}

void fuse_seams(std::span<FaceSoup> soups, std::span<const OpenMesh::Vec3d> points) {
  FacesAt at;
  for (const auto& p : points) at.emplace(p, std::vector<FaceRef>{});
  index_faces(soups, at);
  for (const auto& p : points) {
    fuse_around(soups, p, at);
    drop_if_straight(soups, p, at);
  }
  for (FaceSoup& soup : soups)
    soup.erase(std::remove_if(soup.begin(), soup.end(),
                              [](const SoupFace& f) { return f.points.empty(); }),
               soup.end());
}

}  // namespace roomcad::detail
