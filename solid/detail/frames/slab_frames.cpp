// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/frames/slab_frames.h"

#include <algorithm>
#include <array>
#include <list>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <fmt/format.h>

#include "core/error.h"
#include "solid/detail/frames/slab_edges.h"

namespace roomcad::detail {
namespace {

using K = CGAL::Epick;  // exact predicates; no construction is ever made (the tag below)
struct FaceInfo {
  int nesting = -1;  ///< constraints crossed from outside: odd inside the slab's area
  bool used = false;
};
using Fb = CGAL::Constrained_triangulation_face_base_2<
    K, CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>>;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Face = CDT::Face_handle;

// Gives every face its nesting level: 0 outside, 1 inside the outline, 2 inside a hole.
void mark_nesting(CDT& cdt) {
  std::list<CDT::Edge> border;
  auto flood = [&](Face start, int level) {
    std::list<Face> queue{start};
    while (!queue.empty()) {
      const Face f = queue.front();
      queue.pop_front();
      if (f->info().nesting != -1) continue;
      f->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        if (f->neighbor(i)->info().nesting != -1) continue;
        (cdt.is_constrained({f, i}) ? border.push_back({f, i}) : queue.push_back(f->neighbor(i)));
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    const CDT::Edge e = border.front();
    border.pop_front();
    const Face n = e.first->neighbor(e.second);
    if (n->info().nesting == -1) flood(n, e.first->info().nesting + 1);
  }
}

bool is_inside(const Face& f) { return f->info().nesting % 2 == 1; }

// A convex piece grown from one triangle: corner k's edge runs to corner k + 1 with the face
// `across` it, which the piece may still take in (`open`).
struct Corner {
  CDT::Vertex_handle v;
  Face across;
  bool open = false;
};

Corner corner_of(const CDT& cdt, const Face& f, const CDT::Vertex_handle& v, int opposite) {
  const Face n = f->neighbor(opposite);
  return {
      v, n,
      !cdt.is_constrained({f, opposite}) && !cdt.is_infinite(n) && is_inside(n) && !n->info().used};
}

// Takes in the triangles across the piece's edges while it stays strictly convex (a turn that
// fails once fails for good: taking in more only widens a corner's angle).
Polygon grow_piece(const CDT& cdt, const Face& start) {
  start->info().used = true;
  std::vector<Corner> piece;
  for (int k = 0; k < 3; ++k) piece.push_back(corner_of(cdt, start, start->vertex(k), (k + 2) % 3));
  for (std::size_t k = 0; k < piece.size();) {
    Corner& c = piece[k];
    if (!c.open || c.across->info().used) {
      ++k;
      continue;
    }
    const Face g = c.across;
    const CDT::Vertex_handle a = c.v, b = piece[(k + 1) % piece.size()].v;
    const CDT::Vertex_handle w = g->vertex(3 - g->index(a) - g->index(b));
    const auto& prev = piece[(k + piece.size() - 1) % piece.size()].v->point();
    const auto& next = piece[(k + 2) % piece.size()].v->point();
    if (CGAL::orientation(prev, a->point(), w->point()) != CGAL::LEFT_TURN ||
        CGAL::orientation(w->point(), b->point(), next) != CGAL::LEFT_TURN) {
      c.open = false;
      ++k;
      continue;
    }
    g->info().used = true;
    const Corner to_w = corner_of(cdt, g, a, g->index(b)),
                 from_w = corner_of(cdt, g, w, g->index(a));
    c = to_w;
    piece.insert(piece.begin() + std::ptrdiff_t(k) + 1, from_w);  // k is looked at again
  }
  Polygon out;
  for (const Corner& c : piece) out.push_back({c.v->point().x(), c.v->point().y()});
  return out;
}

// Whether every edge of the slab's outline and holes runs along x or along y, exactly.
bool is_rectilinear(const Slab& slab) {
  const auto along_axes = [](const Polygon& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point2& a = ring[k];
      const Point2& b = ring[(k + 1) % ring.size()];
      if (a.x != b.x && a.y != b.y) return false;
    }
    return true;
  };
  return along_axes(slab.outline) && std::all_of(slab.holes.begin(), slab.holes.end(), along_axes);
}

// A rectilinear slab's area cut into rectangles whose corners are its corners' own coordinates
// (still exact in the plan's doubles, as the triangulation's pieces are): the cells between
// consecutive xs and ys of its corners, inside where an odd number of its edges along y lies
// to their left, joined into runs along x, and runs of equal extent in consecutive rows into
// one rectangle. Fewer pieces than the triangulation's for most floors, and along the axes, as
// the walls on them are: the general path's grid takes their planes (grid_faces.h).
// O(r e) for r rows and e edges.
std::vector<Polygon> rectangles(const Slab& slab) {
  std::vector<double> xs, ys;
  std::vector<std::array<double, 3>> edges_along_y;  // x, low y, high y
  const auto add_ring = [&](const Polygon& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point2& a = ring[k];
      const Point2& b = ring[(k + 1) % ring.size()];
      xs.push_back(a.x), ys.push_back(a.y);
      if (a.x == b.x && a.y != b.y)
        edges_along_y.push_back({a.x, std::min(a.y, b.y), std::max(a.y, b.y)});
    }
  };
  add_ring(slab.outline);
  for (const Polygon& h : slab.holes) add_ring(h);
  for (std::vector<double>* v : {&xs, &ys}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  struct Open {
    std::size_t x0, x1;  // cells [x0, x1) of xs
    double y0;
  };
  std::vector<Open> open, next;
  std::vector<Polygon> out;
  const auto close = [&](const Open& r, double y1) {
    out.push_back({{xs[r.x0], r.y0}, {xs[r.x1], r.y0}, {xs[r.x1], y1}, {xs[r.x0], y1}});
  };
  std::vector<double> crossings;
  for (std::size_t row = 0; row + 1 <= ys.size(); ++row) {
    // The row's runs of cells inside (none above the last y: every open rectangle closes).
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    if (row + 1 < ys.size()) {
      crossings.clear();
      for (const auto& [x, low, high] : edges_along_y)
        if (low <= ys[row] && high >= ys[row + 1]) crossings.push_back(x);
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t c = 0; c + 1 < crossings.size(); c += 2) {
        const auto x0 =
            std::size_t(std::lower_bound(xs.begin(), xs.end(), crossings[c]) - xs.begin());
        const auto x1 =
            std::size_t(std::lower_bound(xs.begin(), xs.end(), crossings[c + 1]) - xs.begin());
        if (x0 < x1) runs.emplace_back(x0, x1);
      }
    }
    next.clear();
    for (const Open& r : open) {
      const auto same = std::find(runs.begin(), runs.end(), std::pair{r.x0, r.x1});
      if (same == runs.end()) {
        close(r, ys[row]);
      } else {
        next.push_back(r);
        runs.erase(same);
      }
    }
    for (const auto& [x0, x1] : runs) next.push_back({x0, x1, ys[row]});
    open.swap(next);
  }
  return out;
}

std::vector<Polygon> convex_pieces(const Slab& slab) {
  CDT cdt;
  auto insert_ring = [&cdt](const Polygon& ring) {
    std::vector<K::Point_2> points;
    for (const Point2& p : ring) points.emplace_back(p.x, p.y);
    cdt.insert_constraint(points.begin(), points.end(), true);
  };
  try {
    insert_ring(slab.outline);
    for (const Polygon& h : slab.holes) insert_ring(h);
  } catch (const CDT::Intersection_of_constraints_exception&) {
    throw PreconditionError(
        fmt::format("build_model: slab '{}' cannot be built: its outline and holes cross "
                    "themselves or each other (they must be simple, the holes inside the "
                    "outline and apart)",
                    slab.id),
        Code::not_buildable);
  }
  if (is_rectilinear(slab)) return rectangles(slab);  // the triangulation checked the rings
  mark_nesting(cdt);
  std::vector<Polygon> pieces;
  for (const Face f : cdt.finite_face_handles())
    if (is_inside(f) && !f->info().used) pieces.push_back(grow_piece(cdt, f));
  return pieces;
}

}  // namespace

std::vector<SlabFrame> make_slab_frames(const Plan& plan, const std::vector<WallFrame>& walls) {
  std::vector<SlabFrame> frames;
  const std::vector<Box2> wall_boxes = wall_boxes_for_laying(walls, plan.site.tolerance);
  for (std::size_t i = 0; i < plan.slabs.size(); ++i) {
    Slab s = plan.slabs[i];
    SlabFrame f{.slab = i,
                .id = s.id,
                .outline = {},
                .holes = {},
                .pieces = {},
                .bottom = s.top - s.thickness,
                .top = s.top,
                .color = s.color};
    if (!(f.bottom < f.top) || s.outline.size() < 3) continue;
    lay_slab_edges_into_walls(s, walls, wall_boxes, plan.site.tolerance);
    f.pieces = convex_pieces(s);
    f.outline = s.outline, f.holes = s.holes;
    if (f.pieces.empty()) continue;
    f.min_x = f.max_x = s.outline.front().x, f.min_y = f.max_y = s.outline.front().y;
    for (const Point2& p : s.outline) {
      f.min_x = std::min(f.min_x, p.x), f.max_x = std::max(f.max_x, p.x);
      f.min_y = std::min(f.min_y, p.y), f.max_y = std::max(f.max_y, p.y);
    }
    frames.push_back(std::move(f));
  }
  return frames;
}

}  // namespace roomcad::detail
