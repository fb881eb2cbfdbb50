// SPDX-License-Identifier: GPL-3.0-or-later
// Collinear merging of picture segments.
#include "render/detail/merge_segments.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>

namespace roomcad::detail {
namespace {

constexpr double kQuantum = 1e7;  // 1 / tolerance of direction (rad) and offset

/// A segment on its canonical line: direction with positive x (or positive y if vertical).
struct LinePiece {
  std::int64_t angle_key = 0;
  std::int64_t offset_key = 0;
  double from = 0.0;  ///< position of `a` along the direction
  double to = 0.0;    ///< of `b`; from < to
  Segment2 segment;   ///< a at `from`, b at `to`
};

LinePiece to_line_piece(Segment2 s) {
  Point2 d{s.b.x - s.a.x, s.b.y - s.a.y};
  if (d.x < 0.0 || (d.x == 0.0 && d.y < 0.0)) {
    std::swap(s.a, s.b);
    d = {-d.x, -d.y};
  }
  const double len = std::hypot(d.x, d.y);
  const Point2 u{d.x / len, d.y / len};
  LinePiece p;
  p.angle_key = std::llround(std::atan2(u.y, u.x) * kQuantum);
  p.offset_key = std::llround((u.x * s.a.y - u.y * s.a.x) * kQuantum);
  p.from = u.x * s.a.x + u.y * s.a.y;
  p.to = u.x * s.b.x + u.y * s.b.y;
  p.segment = s;
  return p;
}

}  // namespace

std::vector<Segment2> merge_collinear(std::vector<Segment2> segments) {
  std::vector<LinePiece> pieces;
  pieces.reserve(segments.size());
  for (const Segment2& s : segments) {
    if (s.a.x != s.b.x || s.a.y != s.b.y) pieces.push_back(to_line_piece(s));
  }
  std::sort(pieces.begin(), pieces.end(), [](const LinePiece& x, const LinePiece& y) {
    return std::tie(x.angle_key, x.offset_key, x.from, x.to) <
           std::tie(y.angle_key, y.offset_key, y.from, y.to);
  });
  std::vector<Segment2> out;
  for (std::size_t i = 0; i < pieces.size();) {
    LinePiece run = pieces[i++];
    while (i < pieces.size() && pieces[i].angle_key == run.angle_key &&
           pieces[i].offset_key == run.offset_key && pieces[i].from <= run.to + 1e-9) {
      if (pieces[i].to > run.to) {
        run.to = pieces[i].to;
        run.segment.b = pieces[i].segment.b;
      }
      ++i;
    }
    out.push_back(run.segment);
  }
  return out;
}

}  // namespace roomcad::detail
