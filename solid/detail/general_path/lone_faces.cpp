// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/lone_faces.h"

#include <algorithm>
#include <numeric>

namespace roomcad::detail {
namespace {

// Whether one of a's lines has every vertex of b on its closed outer side.
bool separated_by_a_line_of(const PlaneSet& set, const PlanePolygon& a, const PlanePolygon& b) {
  return std::any_of(a.lines.begin(), a.lines.end(), [&](PlaneRef line) {
    return std::all_of(b.vertices.begin(), b.vertices.end(),
                       [&](const XPoint& v) { return side(set, line, v) >= 0; });
  });
}

// The contribution as a face of the solid: outward along the plane's normal where its
// primitive lies below, against it where above. vertices[k] of a PlanePolygon is where lines[k]
// and lines[k + 1] meet, so the edge from vertex k to k + 1 lies on lines[k + 1].
SolidFace face_of(const PlaneSet& set, PlaneRef plane, const Contribution& c) {
  const PlanePolygon& p = c.polygon;
  const std::size_t n = p.vertices.size();
  SolidFace face{{plane.id, c.below ? 1 : -1}, c.primitive, {}, {}, {}};
  for (std::size_t k = 0; k < n; ++k) {
    // Seen from outside against the normal, counter-clockwise is the polygon's order reversed.
    const std::size_t v = c.below ? k : n - 1 - k;
    face.vertices.push_back(p.vertices[v]);
    face.lines.push_back(p.lines[c.below ? (k + 1) % n : v]);
    face.rounded.push_back(round_point(set, p.vertices[v]));
  }
  return face;
}

// Marks in `meets` the contributions whose interiors meet another's, from the pairs whose boxes
// meet (a sweep along one axis of the plane's view). @return false, at once, on the first such
// pair if `stop` (the marks then incomplete).
bool mark_meeting(const PlaneSet& set, PlaneRef plane,
                  const std::vector<Contribution>& contributions, bool stop,
                  std::vector<char>& meets) {
  const std::size_t n = contributions.size();
  std::vector<Box3> boxes;
  boxes.reserve(n);
  for (const Contribution& c : contributions) boxes.push_back(box_of(c.polygon.vertices));
  const auto axis = std::size_t((dominant_axis(set, plane.id) + 1) % 3);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].low[axis] < boxes[b].low[axis] ||
           (boxes[a].low[axis] == boxes[b].low[axis] && a < b);
  });
  meets.assign(n, 0);
  bool none = true;
  for (std::size_t m = 0; m < n; ++m)
    for (std::size_t l = m + 1; l < n && boxes[order[l]].low[axis] <= boxes[order[m]].high[axis];
         ++l) {
      const std::size_t a = order[m], b = order[l];
      if ((meets[a] && meets[b]) || !boxes_meet(boxes[a], boxes[b]) ||
          !interiors_meet(set, contributions[a].polygon, contributions[b].polygon))
        continue;
      meets[a] = meets[b] = 1;
      none = false;
      if (stop) return false;
    }
  return none;
}

// Adds a lone contribution's face to `faces`: a solid's face is one, a section or a hole's face
// alone is none.
void add_faces_of(const PlaneSet& set, PlaneRef plane, const Contribution& lone,
                  std::vector<SolidFace>& faces) {
  if (lone.solid && lone.above != lone.below) faces.push_back(face_of(set, plane, lone));
}

}  // namespace

bool interiors_meet(const PlaneSet& set, const PlanePolygon& a, const PlanePolygon& b) {
  return !separated_by_a_line_of(set, a, b) && !separated_by_a_line_of(set, b, a);
}

std::optional<std::vector<SolidFace>> faces_if_apart(
    const PlaneSet& set, PlaneRef plane, const std::vector<Contribution>& contributions) {
  const IntervalScope intervals;
  std::vector<char> meets;
  if (!mark_meeting(set, plane, contributions, true, meets)) return std::nullopt;
  std::vector<SolidFace> faces;
  for (const Contribution& c : contributions) add_faces_of(set, plane, c, faces);
  return faces;
}

std::vector<SolidFace> take_lone_faces(const PlaneSet& set, PlaneRef plane,
                                       std::vector<Contribution>& contributions) {
  const IntervalScope intervals;
  std::vector<char> meets;
  mark_meeting(set, plane, contributions, false, meets);
  std::vector<SolidFace> faces;
  std::vector<Contribution> rest;
  for (std::size_t c = 0; c < contributions.size(); ++c) {
    if (meets[c]) rest.push_back(std::move(contributions[c]));
    else add_faces_of(set, plane, contributions[c], faces);
  }
  contributions = std::move(rest);
  return faces;
}

}  // namespace roomcad::detail
