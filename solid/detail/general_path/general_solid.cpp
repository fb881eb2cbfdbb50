// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/general_solid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>

#include "core/assert.h"
#include "solid/build_model.h"
#include "solid/detail/assembly/classify_face.h"
#include "solid/detail/general_path/convex_pieces.h"
#include "solid/detail/general_path/face_stitching.h"
#include "solid/detail/general_path/grid_faces.h"
#include "solid/detail/general_path/lone_faces.h"
#include "solid/detail/general_path/plane_contributions.h"
#include "solid/detail/general_path/plane_faces.h"
#include "solid/detail/general_path/primitive_section.h"

namespace roomcad::detail {
namespace {

// What one plane's faces are made of.
struct PlaneWork {
  PlaneId plane = 0;
  std::vector<std::pair<std::size_t, std::size_t>> faces;  // (primitive, face) lying on it
  std::vector<std::size_t> crossing;                       // primitives crossing it at a face
  std::vector<Cut> cuts;
  std::optional<PlaneBoolean> boolean;  // kept while its faces have holes
  std::vector<SolidFace> lone;          // faces no other polygon of the plane meets
  PlaneFaces result;                    // the others'
};

// Which objects a cluster's faces belong to.
struct Labels {
  std::span<const WallFrame* const> walls;
  std::span<const SlabFrame* const> slabs;
  int first_opening_object, first_slab_object;
};

// The planes carrying faces, each with the primitives crossing it whose boxes meet a face's.
// Faces of the solid lie on faces of primitives: where only sections lie, the solid is above
// and below alike, so a primitive meeting no face has no part in the plane's faces (nor do
// its section's edges: they split only edges they meet). O(planes x primitives) box tests,
// planes in parallel.
std::vector<PlaneWork> plan_planes(const PlaneSet& set, const std::vector<Primitive>& prims) {
  std::map<PlaneId, PlaneWork> by_plane;
  for (std::size_t p = 0; p < prims.size(); ++p)
    for (std::size_t f = 0; f < prims[p].faces.size(); ++f) {
      PlaneWork& w = by_plane[prims[p].faces[f].plane.id];
      w.plane = prims[p].faces[f].plane.id;
      w.faces.emplace_back(p, f);
    }
  std::vector<PlaneWork> works;
  works.reserve(by_plane.size());
  for (auto& [id, w] : by_plane) works.push_back(std::move(w));
  tbb::parallel_for(std::size_t{0}, works.size(), [&](std::size_t k) {
    PlaneWork& w = works[k];
    std::vector<Box3> faces;
    Box3 all{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (const auto& [p, f] : w.faces) {
      const Box3& face = faces.emplace_back(box_of(prims[p].faces[f].vertices));
      for (std::size_t a = 0; a < 3; ++a) {
        all.low[a] = std::min(all.low[a], face.low[a]);
        all.high[a] = std::max(all.high[a], face.high[a]);
      }
    }
    const IntervalScope intervals;
    for (std::size_t p = 0; p < prims.size(); ++p) {
      if (!boxes_meet(all, prims[p].box)) continue;
      if (std::any_of(w.faces.begin(), w.faces.end(),
                      [&](const auto& pf) { return pf.first == p; }))
        continue;
      bool below = false, above = false;
      for (const XPoint& v : prims[p].vertices) {
        const int s = side(set, {w.plane, 1}, v);
        below = below || s < 0;
        above = above || s > 0;
        if (below && above) break;
      }
      if (below && above && std::any_of(faces.begin(), faces.end(), [&](const Box3& b) {
            return boxes_meet(b, prims[p].box);
          }))
        w.crossing.push_back(p);
    }
  });
  return works;
}

// The face as a polygon counter-clockwise seen from the plane's positive side.
Contribution face_contribution(const Primitive& prim, std::size_t p, std::size_t f) {
  const PlanePolygon& face = prim.faces[f];
  Contribution c{face, p, prim.kind == Primitive::Kind::solid, false, false};
  c.polygon.plane = {face.plane.id, 1};
  if (face.plane.sign > 0) {
    c.below = true;  // looking along the normal: the primitive lies below
    return c;
  }
  c.above = true;
  const std::size_t n = face.lines.size();
  for (std::size_t m = 0; m < n; ++m) {
    c.polygon.lines[m] = face.lines[n - 1 - m];
    c.polygon.vertices[m] = face.vertices[(2 * n - 2 - m) % n];
  }
  return c;
}

// The plane's faces, where its boolean is kept only while they have holes to cut.
void take_faces(PlaneWork& w) {
  w.result = w.boolean->faces();
  if (w.result.holes.empty()) w.boolean.reset();
}

// The plane's first pass: where no two of its polygons overlap, each solid face as it is
// (lone_faces.h); else nothing where it surely has no face; its faces from its grid where its
// polygons are rectangles along its axes, nearly all (grid_faces.h), and `grid` allows; else
// the faces no other polygon meets as they are, and the others' from their 2D boolean. (Lone
// faces taken out of a grid's plane slowed the tower: a grid takes touching rectangles as
// cheaply, and splits their edges where others touch, which stitching would do otherwise.)
void first_pass(const PlaneSet& set, const BoxPlanes& box, const std::vector<Primitive>& prims,
                PlaneWork& w, bool grid) {
  const IntervalScope intervals;
  std::vector<Contribution> contributions;
  for (const auto& [p, f] : w.faces) contributions.push_back(face_contribution(prims[p], p, f));
  for (std::size_t p : w.crossing)
    if (auto section = section_of(set, box, prims[p], {w.plane, 1}))
      contributions.push_back(
          {std::move(*section), p, prims[p].kind == Primitive::Kind::solid, true, true});
  if (auto apart = faces_if_apart(set, {w.plane, 1}, contributions)) {
    w.lone = std::move(*apart);
    return;
  }
  if (has_no_faces(set, contributions)) return;
  if (grid)
    if (auto faces = grid_faces(set, {w.plane, 1}, contributions)) {
      w.result.faces = std::move(*faces);
      return;
    }
  w.lone = take_lone_faces(set, {w.plane, 1}, contributions);
  if (contributions.empty()) return;
  w.boolean.emplace(set, PlaneRef{w.plane, 1}, std::move(contributions));
  take_faces(w);
}

// A segment of a line of the plane through the middle of a hole loop (along a view axis),
// across the owner's box: the owner's faces lie in its polygon, inside that box. None when
// the owner already has a cut on that line (two holes level with each other).
std::optional<Cut> cut_through(PlaneSet& set, const BoxPlanes& box, PlaneId plane,
                               std::size_t owner, const Box3& owner_box,
                               const std::vector<XPoint>& loop, const std::vector<Cut>& cuts) {
  const int k = dominant_axis(set, plane);
  for (const int a : {(k + 1) % 3, (k + 2) % 3}) {
    double lo = INFINITY, hi = -INFINITY;
    // The rounded coordinates, not the intervals: a corner of nearly parallel planes (a sliver
    // between walls drawn over each other) may have an unbounded interval.
    for (const XPoint& v : loop) {
      const double x = round_point(set, v)[std::size_t(a)];
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    const double c = lo + (hi - lo) / 2.0;
    const bool left = std::any_of(loop.begin(), loop.end(), [&](const XPoint& v) {
      return compare_coordinate(set, v, c, a) < 0;
    });
    const bool right = std::any_of(loop.begin(), loop.end(), [&](const XPoint& v) {
      return compare_coordinate(set, v, c, a) > 0;
    });
    if (!left || !right) continue;
    for (const Cut& cut : cuts)
      if (cut.owner == owner && simple_axis(set, cut.line.id) == std::pair{a, c})
        return std::nullopt;
    // Along the cut: the axis other than a and k (the plane's normal has a k part, so the
    // line runs along b). Ends strictly outside the owner's box, or the box's planes where
    // the owner's box is unbounded (a corner of nearly parallel planes).
    const auto b = std::size_t(3 - a - k);
    const double low = owner_box.low[b], high = owner_box.high[b];
    if (!std::isfinite(low) || !std::isfinite(high))
      return Cut{{set.add_axis(a, c), 1}, owner, box.low[b], box.high[b]};
    const double margin = (high - low) / 16.0 + (std::abs(low) + std::abs(high) + 1.0) * 0x1p-30;
    const PlaneId line = set.add_axis(a, c);
    return Cut{
        {line, 1}, owner, set.add_axis(int(b), low - margin), set.add_axis(int(b), high + margin)};
  }
  throw PreconditionError(
      "build_model: a hole in a face of the general path is too thin to cut "
      "(narrower than the doubles can split)",
      Code::not_buildable);
}

// Builds every plane's faces; planes whose faces would have holes get cuts, and only the
// pieces these meet are made again.
void run_planes(PlaneSet& set, const BoxPlanes& box, const std::vector<Primitive>& prims,
                std::vector<PlaneWork>& works, bool grid) {
  tbb::parallel_for(std::size_t{0}, works.size(),
                    [&](std::size_t k) { first_pass(set, box, prims, works[k], grid); });
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < works.size(); ++k)
    if (!works[k].result.holes.empty()) todo.push_back(k);
  for (int round = 1; !todo.empty(); ++round) {
    RC_ASSERT(round < 8, "seven rounds of cuts leave every plane's faces simple polygons");
    std::vector<std::size_t> first_new(todo.size());
    for (std::size_t t = 0; t < todo.size(); ++t) {  // serial: cuts add planes to the set
      PlaneWork& w = works[todo[t]];
      first_new[t] = w.cuts.size();
      for (const auto& [owner, loop] : w.result.holes)
        if (auto cut = cut_through(set, box, w.plane, owner, prims[owner].box, loop, w.cuts))
          w.cuts.push_back(*cut);
    }
    tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t t) {
      PlaneWork& w = works[todo[t]];
      w.boolean->add_cuts(std::span(w.cuts).subspan(first_new[t]));
      take_faces(w);
    });
    std::erase_if(todo, [&](std::size_t k) { return works[k].result.holes.empty(); });
  }
}

SoupFace label_face(const Primitive& prim, const PlaneSet& set, PlaneRef plane,
                    const Labels& labels) {
  SoupFace face;
  if (prim.slab != Primitive::kNoSlab) {
    const SlabFrame& s = *labels.slabs[prim.slab];
    face.kind = FaceKind::slab;
    face.object = labels.first_slab_object + static_cast<int>(s.slab);
    face.color = s.color;
    return face;
  }
  const auto& c = set.approx(plane.id);
  OpenMesh::Vec3d n(CGAL::to_double(c[0]), CGAL::to_double(c[1]), CGAL::to_double(c[2]));
  n = n.normalized() * double(plane.sign);
  const WallFrame& f = *labels.walls[prim.frame];
  face.color = f.color;
  if (prim.kind == Primitive::Kind::solid) {
    face.kind = wall_face_kind(f, n);
    face.object = static_cast<int>(f.wall);
  } else if (std::abs(n[0] * f.normal.x + n[1] * f.normal.y) > 0.9) {
    // A hole's face across its wall is its mouth where other material closes it (a wall in
    // front of a window): that material's face, the host wall's as classify_face has it.
    face.kind = FaceKind::wall_face;
    face.object = static_cast<int>(f.wall);
  } else {
    face.kind = n[2] > 0.5 ? FaceKind::sill : n[2] < -0.5 ? FaceKind::lintel : FaceKind::jamb;
    face.object = labels.first_opening_object + static_cast<int>(prim.opening);
  }
  return face;
}

// The name of a primitive's object in messages: its wall's id, or its slab's.
std::string owner_name(const Primitive& prim, const Labels& labels) {
  if (prim.slab != Primitive::kNoSlab) return fmt::format("slab '{}'", labels.slabs[prim.slab]->id);
  return fmt::format("'{}'", labels.walls[prim.frame]->id);
}

FaceSoup to_face_soup(IndexedSoup soup, std::span<const SolidFace* const> faces,
                      const std::vector<Primitive>& prims, const PlaneSet& set,
                      const Labels& labels) {
  const double tolerance = snap_tolerance(soup.points);
  const IndexedSoup r = snap_soup(std::move(soup), tolerance);
  std::pair<std::size_t, std::size_t> bad;
  const FanSplit fans = split_fans(r.polygons, r.points, bad);
  if (fans.vertex.empty() && !r.polygons.empty()) {
    std::vector<std::string> names;  // each object once (a wall's two faces there are common)
    for (std::size_t k = 0; k < r.polygons.size(); ++k) {
      const auto& poly = r.polygons[k];
      for (std::size_t m = 0; m < poly.size(); ++m)
        if ((poly[m] == bad.first && poly[(m + 1) % poly.size()] == bad.second) ||
            (poly[m] == bad.second && poly[(m + 1) % poly.size()] == bad.first)) {
          std::string name = owner_name(prims[faces[r.tags[k]]->owner], labels);
          if (std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(std::move(name));
        }
    }
    const std::string owners = fmt::format("{}", fmt::join(names, ", "));
    const auto& a = r.points[bad.first];
    const auto& b = r.points[bad.second];
    throw PreconditionError(
        fmt::format("build_model: the solid of walls {} is not 2-manifold: more than "
                    "two of its faces meet at the edge from ({}, {}, {}) to ({}, {}, {}), and "
                    "they cannot be paired across their material",
                    owners, a[0], a[1], a[2], b[0], b[1], b[2]),
        Code::not_buildable);
  }
  // Each face in its own slot (in parallel: tens of thousands of faces in a tall home).
  FaceSoup out(r.polygons.size());
  tbb::parallel_for(std::size_t{0}, r.polygons.size(), [&](std::size_t k) {
    const SolidFace& f = *faces[r.tags[k]];
    SoupFace& face = out[k];
    face = label_face(prims[f.owner], set, f.plane, labels);
    set_corners(face, r.polygons, k, r.points, fans);
  });
  return out;
}

}  // namespace

FaceSoup build_cluster_general(std::span<const WallFrame* const> walls,
                               std::span<const SlabFrame* const> slabs, int first_opening_object,
                               int first_slab_object, bool grid_planes) {
  PlaneSet set;
  const BoxPlanes box = add_box_planes(set, largest_coordinate(walls, slabs));
  std::vector<Primitive> prims =
      make_primitives(set, box, {walls.begin(), walls.end()}, {slabs.begin(), slabs.end()});
  if (prims.empty()) return {};
  use_plane_groups(prims, set.find_equal_planes());
  std::vector<PlaneWork> works = plan_planes(set, prims);
  run_planes(set, box, prims, works, grid_planes);
  std::vector<const SolidFace*> faces;
  for (const PlaneWork& w : works)
    for (const auto* list : {&w.lone, &w.result.faces})
      for (const SolidFace& f : *list) faces.push_back(&f);
  return to_face_soup(stitch_faces(set, faces), faces, prims, set,
                      {walls, slabs, first_opening_object, first_slab_object});
}

}  // namespace roomcad::detail
