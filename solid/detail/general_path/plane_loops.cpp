// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/plane_loops.h"

#include "core/assert.h"

#include <algorithm>

#include "solid/build_model.h"
#include "solid/detail/general_path/convex_pieces.h"

namespace roomcad::detail {
namespace {

// Signs of the cross and dot products of two piece directions, seen from `view`.
struct Turn {
  const PlaneSet& set;
  PlaneRef plane;
  int view;
  int cross(const DirectedPiece& a, int adir, const DirectedPiece& b) const {
    return view * adir * b.dir * orient_normals(set, plane, a.line, b.line);
  }
  int dot(const DirectedPiece& a, int adir, const DirectedPiece& b) const {
    return adir * b.dir * dot_in_plane(set, plane, a.line, b.line);
  }
  // Which quarter of the clockwise turn from `back` (the reversed incoming piece) d lies in:
  // 0 (0, pi), 1 exactly pi, 2 (pi, 2 pi), 3 exactly 2 pi (straight back).
  int half(const DirectedPiece& in, const DirectedPiece& d) const {
    const int c = cross(in, -in.dir, d);
    if (c < 0) return 0;
    if (c > 0) return 2;
    return dot(in, -in.dir, d) < 0 ? 1 : 3;
  }
};

// Of the pieces leaving the end of `in`, the one with the smallest clockwise turn from
// `in` reversed: it bounds the same part of the face as `in`.
std::size_t pick_next(const Turn& turn, const DirectedPiece& in,
                      const std::vector<DirectedPiece>& pieces,
                      const std::vector<std::size_t>& candidates) {
  std::size_t best = candidates.front();
  int best_half = turn.half(in, pieces[best]);
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    const std::size_t c = candidates[k];
    const int h = turn.half(in, pieces[c]);
    if (h < best_half || (h == best_half && (h == 0 || h == 2) &&
                          turn.cross(pieces[c], pieces[c].dir, pieces[best]) < 0)) {
      best = c;
      best_half = h;
    }
  }
  return best;
}

// Whether a loop runs clockwise: the turn at its lowest vertex (lexicographically in the
// plane's two view axes) is a right turn.
bool is_clockwise(const Turn& turn, const std::vector<DirectedPiece>& loop, PointCache& points) {
  const int k = dominant_axis(turn.set, turn.plane.id);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  std::size_t low = 0;
  for (std::size_t m = 1; m < loop.size(); ++m) {
    int c = points.compare(loop[m].from, loop[low].from, i);
    if (c == 0) c = points.compare(loop[m].from, loop[low].from, j);
    if (c < 0) low = m;
  }
  const DirectedPiece& in = loop[(low + loop.size() - 1) % loop.size()];
  return turn.cross(in, in.dir, loop[low]) < 0;
}

}  // namespace

std::vector<PieceLoop> link_loops(PlaneRef plane, int view, std::vector<DirectedPiece> pieces,
                                  PointCache& points) {
  const PlaneSet& set = points.planes();
  std::sort(pieces.begin(), pieces.end(), [](const DirectedPiece& a, const DirectedPiece& b) {
    return a.from < b.from || (a.from == b.from && a.to < b.to);
  });
  const Turn turn{set, plane, view};
  std::vector<char> used(pieces.size(), 0);
  std::vector<std::size_t> candidates;
  std::vector<PieceLoop> loops;
  for (std::size_t start = 0; start < pieces.size(); ++start) {
    if (used[start]) continue;
    PieceLoop loop;
    std::size_t cur = start;
    while (true) {
      used[cur] = 1;
      loop.pieces.push_back(pieces[cur]);
      const std::size_t v = pieces[cur].to;
      // The successor is chosen among all pieces leaving v (used or not), so it is a fixed
      // permutation of the pieces and every loop closes on its start.
      candidates.clear();
      auto it = std::lower_bound(pieces.begin(), pieces.end(), v,
                                 [](const DirectedPiece& p, std::size_t x) { return p.from < x; });
      for (; it != pieces.end() && it->from == v; ++it)
        candidates.push_back(std::size_t(it - pieces.begin()));
      RC_ASSERT(!candidates.empty(), "every boundary piece of a plane's faces has a successor");
      const std::size_t next = candidates.size() == 1
                                   ? candidates.front()
                                   : pick_next(turn, pieces[cur], pieces, candidates);
      if (next == start) break;
      RC_ASSERT(!used[next], "the boundary loops of a plane's faces do not cross themselves");
      cur = next;
    }
    loop.is_hole = is_clockwise(turn, loop.pieces, points);
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace roomcad::detail
