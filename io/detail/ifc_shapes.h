// SPDX-License-Identifier: GPL-3.0-or-later
// The geometry of the IFC export (io/ifc_export.h): points, profiles, extrusions and face sets
// written as STEP instances, and each wall's footprint as the export cuts it.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "geometry/joins.h"
#include "io/step_file.h"
#include "plan/plan.h"

namespace roomcad::io_detail {

/// The STEP writer with the instances every shape refers to, shared instead of repeated.
struct IfcShapeWriter {
  step::Writer& out;
  int body_context = 0;                   ///< 'Body' sub-context (MODEL_VIEW)
  int axis_context = 0;                   ///< 'Axis' sub-context (GRAPH_VIEW)
  int up = 0;                             ///< IFCDIRECTION((0.,0.,1.))
  std::map<std::uint32_t, int> styles{};  ///< colour (0xrrggbb) -> its IFCSURFACESTYLE

  /// @return a new IFCCARTESIANPOINT of 2 (or 3) coordinates, metres.
  int point(Point2 p);
  int point(Point2 p, double z);
  /// @return a new IFCAXIS2PLACEMENT3D at `at`, z axis `axis`, x axis `x_axis` (unit vectors).
  int placement(Point2 at, double z, std::array<double, 3> axis, std::array<double, 3> x_axis);
  /// @return a new closed IFCPOLYLINE through `ring` (its first point repeated at the end).
  int closed_polyline(const std::vector<Point2>& ring);
  /// @return an IFCEXTRUDEDAREASOLID of the profile `outline` minus `holes` (in the plane of
  ///   `position`, 0 for the placement's own), extruded `depth` metres along its z axis, styled
  ///   in `color`.
  int extrusion(const std::vector<Point2>& outline, const std::vector<std::vector<Point2>>& holes,
                int position, double depth, Color color);
  /// @return an IFCTRIANGULATEDFACESET (closed) of the points and the triangles (indices from 0,
  ///   counter-clockwise seen from outside), styled in `color`.
  int face_set(const std::vector<std::array<double, 3>>& points,
               const std::vector<std::array<int, 3>>& triangles, Color color);
  /// @return an IFCPRODUCTDEFINITIONSHAPE of a 'Body' representation of type `type`
  ///   ('SweptSolid', 'Tessellation') holding `items`, and, if axis >= 0, an 'Axis' one.
  int product_shape(const std::string& type, const std::vector<int>& items, int axis = -1);

 private:
  int style_of(Color color);
  void style(int item, Color color);
};

/// A plan's walls with their joins, and each wall's joins (indices into joins.pairs), so that
/// a wall's joins are found in O(its joins).
struct JoinedWalls {
  JoinedWalls(const Plan& plan, const Joins& joins);
  const Plan& plan;
  const Joins& joins;
  std::vector<std::vector<std::size_t>> joins_of;
};

/// The footprint the export gives each wall: wall_footprint (mitred ends), and at the end of a
/// wall that stops on another's centre line (a T: the end within tolerance of exactly one other
/// wall's centre line, away from its ends) cut back to that wall's face, so that joined walls'
/// bodies do not overlap and their volumes add up to the united solid's.
/// @param walls a plan with heights absolute (with_absolute_heights), validated, and
///   find_joins of it.
/// @return corners counter-clockwise, as wall_footprint. O(joins of the wall).
[[nodiscard]] std::array<Point2, 4> export_footprint(const JoinedWalls& walls, std::size_t wall);

/// @return the Axis representation's IFCPOLYLINE through `line` (a wall's from, its chord
///   corners if it is an arc, and its to).
int wall_axis(IfcShapeWriter& shapes, const std::vector<Point2>& line);

/// @return the body item of a wall whose base is at z = 0 of its placement: an extrusion of the
///   footprint when its top is level, else a face set (the top the plane through its top edge).
int wall_body(IfcShapeWriter& shapes, const Wall& wall, const std::array<Point2, 4>& footprint);

/// The void of one piece of an opening in an arc wall: the part of the opening on one chord
/// (with_arcs_as_chords), as the build cuts it. In plan, the piece's span along the chord
/// reaching one thickness to either side of its centre line (past both faces), ending square
/// or, where the piece runs on into the next chord, on the chords' mitre line (the footprint's
/// end there); extruded up from the sill by the height.
/// @param chord     the chord wall; @param footprint its export_footprint
/// @param piece     the piece on it (offset and width along the chord, sill, height)
/// @param mitred    per end (from, to): the piece runs on through the mitre there
/// @return the IFCEXTRUDEDAREASOLID, in the wall's placement (z = 0 at its base). O(1).
int chord_piece_void(IfcShapeWriter& shapes, const Wall& chord,
                     const std::array<Point2, 4>& footprint, const Opening& piece,
                     std::array<bool, 2> mitred);

}  // namespace roomcad::io_detail
