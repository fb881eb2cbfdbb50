// SPDX-License-Identifier: GPL-3.0-or-later
// The faces of the solid on one plane (general_solid.h): exact 2D booleans in the plane.
//
// Each primitive near the plane contributes a convex polygon: where it crosses the plane, its
// section (it lies both just above and just below there); where one of its faces lies on the
// plane, that face (it lies just above, or just below). At a point of the plane the solid
// (solids minus holes) is just below and not just above: a face looking along the normal
// there; just above and not below: a face looking against it. Every polygon edge is split
// where other edges cross or touch it; each piece is then one straight segment that no other
// polygon boundary crosses, so both of its sides are each inside or outside every polygon,
// which the signs of the polygons' lines at its ends decide exactly. A piece bounds a face
// where the two sides differ; the face on each side belongs to an owner (the primitive whose
// face it is: the lowest-numbered solid with a face there, else the lowest hole), so faces
// are split where owners change and each gets an exact label. Pieces are linked into loops
// (plane_loops.h). A face with a hole is cut through the hole by a line of its owner's (a
// `Cut`), so every face is one simple polygon.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "solid/detail/general_path/convex_pieces.h"
#include "solid/detail/general_path/exact_planes.h"

namespace roomcad::detail {

/// A primitive's polygon in the plane.
struct Contribution {
  PlanePolygon polygon;  ///< counter-clockwise seen from the plane's positive side
  std::size_t primitive = 0;
  bool solid = true;
  bool above = false;  ///< the primitive is just above the plane (its positive side) there
  bool below = false;
};

/// The owners of the faces at a place of the plane (-1: none): the primitive whose face looks
/// along the plane's normal there (`up`), and the one whose face looks against it (`down`).
struct FaceOwners {
  long up = -1, down = -1;
};

/// What lies just above and just below one place of the plane (a side of a piece, a cell of a
/// grid), gathered from the contributions covering it; decides the faces there.
class Presence {
 public:
  /// Adds a contribution that covers the place.
  void add(const Contribution& c) {
    auto lowest = [&](long& slot) {
      slot = slot < 0 ? long(c.primitive) : std::min(slot, long(c.primitive));
    };
    (c.solid ? solid_above_ : hole_above_) |= c.above;
    (c.solid ? solid_below_ : hole_below_) |= c.below;
    if (c.below && !c.above) lowest(c.solid ? solid_face_below_ : hole_face_below_);
    if (c.above && !c.below) lowest(c.solid ? solid_face_above_ : hole_face_above_);
  }
  /// @return the faces there: the solid (solids minus holes) just below and not just above is
  ///         a face looking up, owned by the lowest-numbered hole with a face there if a solid
  ///         lies above too (the hole's mouth), else the lowest-numbered solid with a face
  ///         there; the other way round for a face looking down. O(1).
  [[nodiscard]] FaceOwners owners() const {
    FaceOwners out;
    const bool below = solid_below_ && !hole_below_, above = solid_above_ && !hole_above_;
    if (below && !above) out.up = solid_above_ ? hole_face_above_ : solid_face_below_;
    if (above && !below) out.down = solid_below_ ? hole_face_below_ : solid_face_above_;
    return out;
  }

 private:
  bool solid_above_ = false, solid_below_ = false, hole_above_ = false, hole_below_ = false;
  long solid_face_below_ = -1, solid_face_above_ = -1, hole_face_above_ = -1, hole_face_below_ = -1;
};

/// A segment of a line of the plane that splits the faces of one owner: the part of `line`
/// between the planes `low` and `high` (planes across it, normals pointing the same way along
/// it), which reaches across the owner's polygon, so no other owner's edges need splitting
/// far away.
struct Cut {
  PlaneRef line;
  std::size_t owner = 0;
  PlaneId low = 0, high = 0;
};

/// A face of the solid: a simple polygon on `plane` (oriented outward: along the normal of
/// the plane a PlaneBoolean is built on, or against it).
struct SolidFace {
  PlaneRef plane;
  std::size_t owner = 0;         ///< the primitive whose face it is
  std::vector<XPoint> vertices;  ///< counter-clockwise seen from outside
  std::vector<PlaneRef> lines;   ///< lines[k]: the line of edge vertices[k] -> vertices[k + 1]
  std::vector<std::array<double, 3>> rounded;  ///< each vertex rounded to the nearest doubles
};

struct PlaneFaces {
  std::vector<SolidFace> faces;  ///< none while there are holes
  /// Loops that would be holes of a face (owner, vertices): cut through them and run again.
  std::vector<std::pair<std::size_t, std::vector<XPoint>>> holes;
};

/// The faces of the solid on one plane. Built once; where faces have holes, cuts are added
/// and only the pieces they meet are made and classified again.
class PlaneBoolean {
 public:
  /// Splits every edge of the contributions where others cross or touch it and classifies
  /// the pieces, walking along each edge: its first piece against the c polygons around it,
  /// each next one against the polygons whose edges split it off. O(n log n + k) predicates
  /// for n polygon edges and k crossings, plus O(n c + k) for the classification.
  /// @param[in] plane          canonical orientation (sign +1)
  /// @param[in] contributions  every primitive near the plane with area in it
  PlaneBoolean(const PlaneSet& set, PlaneRef plane, std::vector<Contribution> contributions);
  ~PlaneBoolean();
  PlaneBoolean(PlaneBoolean&&) noexcept;
  PlaneBoolean& operator=(PlaneBoolean&&) noexcept;

  /// Adds lines splitting their owners' faces. O(m n) box tests for m cuts, plus the
  /// predicates of the pieces they make.
  /// @pre every plane the cuts name is in `set`.
  void add_cuts(std::span<const Cut> cuts);

  /// @return the faces, each owner's split by its cuts, when no loop is a hole; else only the
  ///         hole loops (no faces: the plane is to be cut). O(p log p) plus the loops'
  ///         angular sorts.
  [[nodiscard]] PlaneFaces faces();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace roomcad::detail
