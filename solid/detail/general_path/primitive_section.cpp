// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/primitive_section.h"

#include <cstddef>
#include <cstdint>

#include <boost/container/small_vector.hpp>

namespace roomcad::detail {
namespace {

constexpr std::size_t kNone = SIZE_MAX;

}  // namespace

// Per face, the edge where it passes from the plane's negative side back to its positive one
// (its exit; an edge m runs on lines[m] from vertex m - 1 to vertex m). Seen from the plane's
// positive side, walking the section counter-clockwise, a face's part runs from its entry to
// its exit (the solid on the left), and the next face is the one across that edge.
std::optional<PlanePolygon> section_from_crossings(const PlaneSet& set, const Primitive& prim,
                                                   PlaneRef plane) {
  const std::size_t faces = prim.faces.size();
  boost::container::small_vector<std::size_t, 16> exit(faces, kNone);
  boost::container::small_vector<int, 16> s;
  std::size_t crossing = 0, first = kNone;
  for (std::size_t f = 0; f < faces; ++f) {
    const PlanePolygon& face = prim.faces[f];
    const std::size_t n = face.vertices.size();
    s.resize(n);
    for (std::size_t m = 0; m < n; ++m)
      if ((s[m] = side(set, plane, face.vertices[m])) == 0) return std::nullopt;
    std::size_t entries = 0, exits = 0;
    for (std::size_t m = 0; m < n; ++m) {
      const int before = s[(m + n - 1) % n];
      entries += before > 0 && s[m] < 0;
      if (before < 0 && s[m] > 0) ++exits, exit[f] = m;
    }
    if (entries != exits || exits > 1) return std::nullopt;  // not convex: never expected
    if (exits == 1) {
      ++crossing;
      if (first == kNone) first = f;
    }
  }
  if (crossing < 3) return std::nullopt;
  PlanePolygon section{plane, {}, {}};
  section.lines.reserve(crossing);
  section.vertices.reserve(crossing);
  for (std::size_t f = first; section.lines.size() < crossing;) {
    const PlanePolygon& face = prim.faces[f];
    const PlaneId next = face.lines[exit[f]].id;
    section.lines.push_back(face.plane);
    section.vertices.push_back(make_point(set, plane.id, face.plane.id, next));
    f = kNone;
    for (std::size_t g = 0; g < faces && f == kNone; ++g)
      if (prim.faces[g].plane.id == next && exit[g] != kNone) f = g;
    if (f == kNone || (f == first) != (section.lines.size() == crossing)) return std::nullopt;
  }
  return section;
}

std::optional<PlanePolygon> section_by_clipping(const PlaneSet& set, const BoxPlanes& box,
                                                const Primitive& primitive, PlaneRef plane) {
  PlanePolygon clipped = box_polygon(set, box, plane);
  for (const PlanePolygon& f : primitive.faces)
    if (!clip_polygon(set, clipped, f.plane)) return std::nullopt;
  return clipped;
}

std::optional<PlanePolygon> section_of(const PlaneSet& set, const BoxPlanes& box,
                                       const Primitive& primitive, PlaneRef plane) {
  if (auto section = section_from_crossings(set, primitive, plane)) return section;
  return section_by_clipping(set, box, primitive, plane);
}

}  // namespace roomcad::detail
