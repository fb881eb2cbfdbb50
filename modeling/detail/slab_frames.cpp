// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/detail/slab_frames.h"

#include <algorithm>
#include <list>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <fmt/format.h>

#include "core/error.h"
#include "modeling/detail/slab_edges.h"

namespace roomcad::detail {
namespace {

using K = CGAL::Epick;  // exact predicates; no construction is ever made (the tag below)
struct FaceInfo {
  int nesting = -1;  ///< constraints crossed from outside: odd inside the slab's area
  bool used = false;
};
using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>>;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
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
  return {v, n, !cdt.is_constrained({f, opposite}) && !cdt.is_infinite(n) && is_inside(n) && !n->info().used};
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
    const Corner to_w = corner_of(cdt, g, a, g->index(b)), from_w = corner_of(cdt, g, w, g->index(a));
    c = to_w;
    piece.insert(piece.begin() + std::ptrdiff_t(k) + 1, from_w);  // k is looked at again
  }
  Polygon out;
  for (const Corner& c : piece) out.push_back({c.v->point().x(), c.v->point().y()});
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
    throw PreconditionError(fmt::format("build_model: slab '{}' cannot be built: its outline and holes cross "
                                        "themselves or each other (they must be simple, the holes inside the "
                                        "outline and apart)", slab.id), Code::not_buildable);
  }
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
    SlabFrame f{.slab = i, .outline = {}, .holes = {}, .pieces = {}, .bottom = s.top - s.thickness, .top = s.top,
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
