// SPDX-License-Identifier: GPL-3.0-or-later
// The shapes the door and space rules test, in any rule number type: a wall's frame, a door
// leaf's swept quarter disc, the clear rectangle in front of a door, and wall footprints cut
// at their doors (what a person walks between).
//
// The leaf (plan format, "Rule sets"): it turns about the end of its opening nearer the
// wall's `from` for `hinge: left` (the other end for `right`), and opens to the wall's left
// side (seen from `from` to `to`) for `swing: in`, to its right side for `out`. Its swept
// area is the quarter disc of radius `width` about the hinge, on the swing side of the wall
// face; the hinge lies on that face.
#pragma once

#include <algorithm>
#include <vector>

#include "geometry/joins.h"
#include "validation/rules/convex.h"

namespace roomcad::rules {

/// A wall's frame: `from`, the unit vector along it, the unit left normal, half thickness.
template <class NT>
struct WallFrame {
  Pt<NT> origin;
  Pt<NT> u;
  Pt<NT> n;
  NT half;
  /// @return the point `along` metres from `from` and `across` metres to the left.
  Pt<NT> at(const NT& along, const NT& across) const { return origin + (along * u + across * n); }
};

template <class NT>
WallFrame<NT> wall_frame(const Wall& w) {
  const Pt<NT> a = exact::to_pt<NT>(w.from);
  const Pt<NT> d = exact::to_pt<NT>(w.to) - a;
  const NT length = exact::root(exact::dot(d, d));
  const Pt<NT> u{d.x / length, d.y / length};
  return {a, u, Pt<NT>{-u.y, u.x}, NT(w.thickness) / NT(2)};
}

/// @return +1 for the wall's left side (swing in), -1 for its right side.
inline int side_of(Swing swing) { return swing == Swing::in ? 1 : -1; }

/// A door leaf's swept quarter disc: centre (hinge), squared radius, and its bounding square
/// (the quadrant cut to the radius), counter-clockwise.
template <class NT>
struct LeafSweep {
  Pt<NT> hinge;
  NT radius2;
  Poly<NT> square;
};

template <class NT>
LeafSweep<NT> leaf_sweep(const Wall& w, const Opening& o, Hinge hinge, Swing swing) {
  const WallFrame<NT> f = wall_frame<NT>(w);
  const int s = side_of(swing);
  const int c = hinge == Hinge::left ? 1 : -1;  // from the hinge towards the closed leaf's tip
  const NT hinge_u = hinge == Hinge::left ? NT(o.offset) : NT(o.offset) + NT(o.width);
  const NT r(o.width);
  const Pt<NT> h = f.at(hinge_u, NT(s) * f.half);
  const Pt<NT> along = NT(c) * r * f.u;
  const Pt<NT> out = NT(s) * r * f.n;
  std::array<Pt<NT>, 4> corners{h, h + along, h + along + out, h + out};
  if (c * s < 0) std::reverse(corners.begin(), corners.end());  // keep counter-clockwise
  return {h, r * r, make_poly(corners)};
}

/// The free rectangle in front of a door on its push side (the side its leaf does not open
/// to): `width` along the wall, centred on the opening, `depth` away from the wall face.
template <class NT>
Poly<NT> clearance_rectangle(const Wall& w, const Opening& o, Swing swing, double width,
                             double depth) {
  const WallFrame<NT> f = wall_frame<NT>(w);
  const int p = -side_of(swing);
  const NT middle = NT(o.offset) + NT(o.width) / NT(2);
  const NT lo = middle - NT(width) / NT(2), hi = middle + NT(width) / NT(2);
  const NT face = NT(p) * f.half, far = NT(p) * (f.half + NT(depth));
  std::array<Pt<NT>, 4> corners{f.at(lo, face), f.at(hi, face), f.at(hi, far), f.at(lo, far)};
  if (p < 0) std::reverse(corners.begin(), corners.end());
  return make_poly(corners);
}

/// @return wall w's mitred footprint (modeling's exact corners), counter-clockwise.
template <class NT>
Poly<NT> wall_polygon(const Plan& plan, const Joins& joins, std::size_t w) {
  return make_poly(exact::wall_corners<NT>(plan, joins, w));
}

/// The door holes of a wall, as spans [offset, offset + width] along it.
struct Span {
  double lo;
  double hi;
};

/// @return the pieces of wall w's footprint between its door holes (`holes` sorted by lo),
///         each convex: holes.size() + 1 of them, some maybe without area (a door at an end).
template <class NT>
std::vector<Poly<NT>> wall_pieces(const Plan& plan, const Joins& joins, std::size_t w,
                                  const std::vector<Span>& holes) {
  const Poly<NT> whole = wall_polygon<NT>(plan, joins, w);
  const WallFrame<NT> f = wall_frame<NT>(plan.walls[w]);
  std::vector<Poly<NT>> out;
  Poly<NT> rest = whole;
  for (const Span& s : holes) {
    const Pt<NT> start = f.at(NT(s.lo), NT(0)), end = f.at(NT(s.hi), NT(0));
    out.push_back(clip_left(rest, start, start + f.n));  // u <= lo
    rest = clip_left(rest, end, end - f.n);              // u >= hi
  }
  out.push_back(rest);
  return out;
}

}  // namespace roomcad::rules
