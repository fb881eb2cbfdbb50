// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/plane_contributions.h"

#include <algorithm>
#include <optional>
#include <tuple>
#include <utility>

#include "core/flat_index.h"

namespace roomcad::detail {
namespace {

// The contributions whose flag in `dropped` is 0, in their order.
std::vector<Contribution> without_dropped(std::vector<Contribution> contributions,
                                          const std::vector<char>& dropped) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < contributions.size(); ++k)
    if (!dropped[k]) {
      if (n != k) contributions[n] = std::move(contributions[k]);
      ++n;
    }
  contributions.resize(n);
  return contributions;
}

// Whether point v lies in convex polygon `polygon` (closed). Exact.
bool holds_point(const PlaneSet& set, const PlanePolygon& polygon, const XPoint& v) {
  return std::none_of(polygon.lines.begin(), polygon.lines.end(),
                      [&](PlaneRef t) { return side(set, t, v) > 0; });
}

// Whether convex polygon `inner` lies in convex polygon `outer` (both closed). Exact.
bool lies_in(const PlaneSet& set, const PlanePolygon& inner, const PlanePolygon& outer) {
  return std::all_of(inner.vertices.begin(), inner.vertices.end(),
                     [&](const XPoint& v) { return holds_point(set, outer, v); });
}

// Whether convex polygon `face` lies in the union of the convex polygons `covers` (of its
// plane): nothing is left of it once each cover is taken away (a convex polygon minus a convex
// one is at most one convex piece per line of the latter). A corner in no cover says no at
// once, before any piece is made: most faces that are not covered have one. Gives up (false)
// past 64 pieces. Exact.
bool lies_in_union(const PlaneSet& set, const PlanePolygon& face,
                   const std::vector<const PlanePolygon*>& covers) {
  const auto in_a_cover = [&](const XPoint& v) {
    return std::any_of(covers.begin(), covers.end(),
                       [&](const PlanePolygon* c) { return holds_point(set, *c, v); });
  };
  if (!std::all_of(face.vertices.begin(), face.vertices.end(), in_a_cover)) return false;
  constexpr std::size_t kMostPieces = 64;
  std::vector<PlanePolygon> left{face}, next;
  for (const PlanePolygon* cover : covers) {
    next.clear();
    for (PlanePolygon& piece : left)
      for (const PlaneRef& t : cover->lines) {
        PlanePolygon outside = piece;  // the part beyond t, inside the lines before it
        if (clip_polygon(set, outside, {t.id, -t.sign})) next.push_back(std::move(outside));
        if (!clip_polygon(set, piece, t)) break;  // none of it within t
      }
    if (next.size() > kMostPieces) return false;
    left.swap(next);
    if (left.empty()) return true;
  }
  return false;
}

// Each contribution's polygon's box, in their order.
std::vector<Box3> boxes_of(const std::vector<Contribution>& contributions) {
  std::vector<Box3> boxes;
  boxes.reserve(contributions.size());
  for (const Contribution& c : contributions) boxes.push_back(box_of(c.polygon.vertices));
  return boxes;
}

// A point near the middle of convex polygon `polygon`: the mean of its corners' interval
// midpoints, as explicit doubles (so up to a rounding off the polygon's plane); none where
// those are not finite. A guess, for ordering and a shortcut whose false is allowed to be
// wrong, never for a verdict.
std::optional<XPoint> middle_of(const PlanePolygon& polygon) {
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  for (const XPoint& v : polygon.vertices)
    for (std::size_t k = 0; k < 3; ++k) sum[k] += v.approx[k].inf() / 2.0 + v.approx[k].sup() / 2.0;
  const auto n = double(polygon.vertices.size());
  for (double& x : sum) {
    x /= n;
    if (!std::isfinite(x)) return std::nullopt;
  }
  return make_point(sum[0], sum[1], sum[2]);
}

}  // namespace

// The contributions with equal polygons of one kind (solid or hole, above, below) made one: the
// first of them, owned by the lowest-numbered primitive among them (the owner classify picks
// where they lie). They would only repeat each other's edges and pieces: walls drawn over one
// another give many. O(n log n) plus the corners of polygons of one hash.
std::vector<Contribution> without_duplicates(std::vector<Contribution> contributions) {
  using Corners = std::vector<std::array<std::uint64_t, 3>>;
  std::vector<Corners> corners(contributions.size());
  std::vector<std::pair<std::uint64_t, std::size_t>> by_hash;  // (hash, contribution)
  by_hash.reserve(contributions.size());
  for (std::size_t k = 0; k < contributions.size(); ++k) {
    const Contribution& c = contributions[k];
    Corners& key = corners[k];
    for (const XPoint& v : c.polygon.vertices) key.push_back(representation_key(v));
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    std::uint64_t hash = (c.solid ? 1 : 0) | (c.above ? 2 : 0) | (c.below ? 4 : 0);
    for (const auto& corner : key) hash = mix_bits(hash ^ BitsHash{}(corner));
    by_hash.emplace_back(hash, k);
  }
  std::sort(by_hash.begin(), by_hash.end());
  std::vector<char> dropped(contributions.size(), 0);
  for (std::size_t a = 0; a < by_hash.size(); ++a) {
    const std::size_t first = by_hash[a].second;
    if (dropped[first]) continue;
    Contribution& kept = contributions[first];
    for (std::size_t b = a + 1; b < by_hash.size() && by_hash[b].first == by_hash[a].first; ++b) {
      Contribution& other = contributions[by_hash[b].second];
      if (dropped[by_hash[b].second] || corners[by_hash[b].second] != corners[first] ||
          other.solid != kept.solid || other.above != kept.above || other.below != kept.below)
        continue;
      kept.primitive = std::min(kept.primitive, other.primitive);
      dropped[by_hash[b].second] = 1;
    }
  }
  return without_dropped(std::move(contributions), dropped);
}

// The contributions without those lying in a section that makes them irrelevant: in a solid
// section every solid polygon (solid lies above and below there whatever they say), in a hole
// section every polygon (holes take both sides away). Where a face lies inside a solid
// section, only holes make it and own it. Walls drawn over one another give many: a lower
// storey's wall top inside the section of a wall across it. O(n s) box tests for s sections,
// plus the side tests of containment where boxes meet; each polygon is tested against the
// kept sections.
std::vector<Contribution> without_covered(const PlaneSet& set,
                                          std::vector<Contribution> contributions) {
  std::vector<std::size_t> sections;
  for (std::size_t s = 0; s < contributions.size(); ++s)
    if (contributions[s].above && contributions[s].below) sections.push_back(s);
  if (sections.empty()) return contributions;
  const std::vector<Box3> boxes = boxes_of(contributions);
  std::vector<char> dropped(contributions.size(), 0);
  for (std::size_t p = 0; p < contributions.size(); ++p)
    for (const std::size_t s : sections) {
      const Contribution& section = contributions[s];
      if (s == p || dropped[s] || (section.solid && !contributions[p].solid) ||
          !boxes_meet(boxes[p], boxes[s]) ||
          !lies_in(set, contributions[p].polygon, section.polygon))
        continue;
      dropped[p] = 1;
      break;
    }
  return without_dropped(std::move(contributions), dropped);
}

bool has_no_faces(const PlaneSet& set, const std::vector<Contribution>& contributions) {
  const IntervalScope intervals;
  const std::vector<Box3> boxes = boxes_of(contributions);
  std::vector<const PlanePolygon*> covers;
  const PlanePolygon* last = nullptr;  // the cover that held the last face: often the next too
  for (std::size_t f = 0; f < contributions.size(); ++f) {
    const Contribution& face = contributions[f];
    if (face.above == face.below) continue;  // a section
    if (!face.solid) return false;
    // The solid polygons on the face's other side, near it: usually one holds it whole.
    covers.clear();
    for (std::size_t g = 0; g < contributions.size(); ++g) {
      const Contribution& other = contributions[g];
      if (other.solid && (face.below ? other.above : other.below) && boxes_meet(boxes[f], boxes[g]))
        covers.push_back(&other.polygon);
    }
    if (last && std::find(covers.begin(), covers.end(), last) != covers.end() &&
        lies_in(set, face.polygon, *last))
      continue;
    // A face whose middle no cover holds is (nearly surely) not covered: false at once, before
    // the exact tests of containment. Otherwise the covers holding the middle go first.
    if (const auto middle = middle_of(face.polygon)) {
      const auto holders = std::stable_partition(
          covers.begin(), covers.end(),
          [&](const PlanePolygon* c) { return holds_point(set, *c, *middle); });
      if (holders == covers.begin()) return false;
    }
    const auto holder = std::find_if(covers.begin(), covers.end(), [&](const PlanePolygon* c) {
      return lies_in(set, face.polygon, *c);
    });
    if (holder != covers.end()) {
      last = *holder;
      continue;
    }
    if (!lies_in_union(set, face.polygon, covers)) return false;
  }
  return true;
}

}  // namespace roomcad::detail
