// SPDX-License-Identifier: GPL-3.0-or-later
// CAD line drawings of the model: elevations, isometric and camera views with hidden lines
// removed exactly in object space, then laid out on paper at a scale (mm).
//
// Views (`roomcad draw --view`), each named after the face it shows:
//   north  the north elevation: the viewer stands north looking south (east on the left);
//   south  looking north (east on the right); east  looking west (north on the right);
//   west   looking east (north on the left); all with z up, orthographic.
//   iso    orthographic from the south-west and above, along (1, 1, -1): true isometric.
//   camera:ID  the plan camera ID (perspective, or orthographic if the camera is).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/parts.h"
#include "mesh/solid_mesh.h"
#include "plan/plan.h"
#include "render/floor_plan.h"

namespace roomcad {

enum class HiddenLines { off, dashed };

/// How a drawing looks at the model.
struct LineView {
  std::string name;  ///< for the title, e.g. "North elevation (looking south)"
  bool perspective = false;
  glm::dvec3 eye{0.0};          ///< perspective: the eye, metres
  glm::dvec3 forward{0, 1, 0};  ///< view direction, non-zero; kept as given for exact tests
  glm::dvec3 up{0, 0, 1};       ///< not parallel to forward
  double fov_deg = 50.0;        ///< perspective: vertical field of view
};

/// @return the view named north|south|east|west|iso, or nullopt. O(1).
[[nodiscard]] std::optional<LineView> preset_line_view(std::string_view name);

/// @return the view of a plan camera (its projection; an orthographic camera draws at the
///         drawing's scale like an elevation). O(1).
[[nodiscard]] LineView camera_line_view(const Camera& camera);

/// A segment in the picture plane: orthographic views in metres (x right, y up), perspective
/// views in tangents of the angle off the view axis (x / depth, y / depth).
struct Segment2 {
  Point2 a;
  Point2 b;
};

struct HiddenLineResult {
  std::vector<Segment2> visible;  ///< collinear touching pieces merged
  std::vector<Segment2> hidden;   ///< merged likewise
  std::size_t feature_edges = 0;  ///< edges considered (after the near-plane clip)
  std::size_t pieces = 0;         ///< pieces classified, before merging
};

/// Removes hidden lines. Each feature edge (boundary, or between faces not in one plane) is
/// split where its projection crosses, or is touched by, the projection of another feature
/// edge (visibility can change only there, as faces do not pierce each other), and each piece
/// is classified at its midpoint: hidden if the segment from it towards the viewer meets a
/// face (exact CGAL test). Faces seen edge-on hide nothing; a face closer than 1e-7 m in front
/// of an edge does not hide it (the edge's own faces touch it). Perspective views clip edges
/// at the near plane (kPerspectiveNear); nothing is clipped to a frame here.
/// Broad phase: a uniform grid over the picture. Deterministic, parallel over edges.
/// Cost O(E * k + P * f) for E edges with k neighbours in the grid, P pieces, f faces per cell.
[[nodiscard]] HiddenLineResult remove_hidden_lines(const Model& model, const Parts& parts,
                                                   const LineView& view);

struct LineDrawingOptions {
  double scale = 50.0;  ///< 1:scale; unused by perspective views
  HiddenLines hidden = HiddenLines::dashed;
  Parts parts{};  ///< walls, floor outline, fixtures
};

/// A line drawing on paper, mm, y down.
struct LineDrawing {
  double width = 0.0;
  double height = 0.0;
  std::vector<PaperLine> visible;
  std::vector<PaperLine> hidden;              ///< empty with HiddenLines::off
  std::vector<PaperLine> frame;               ///< the picture's border (perspective views)
  std::vector<PaperPolygon> scale_bar_black;  ///< orthographic views only
  std::vector<PaperPolygon> scale_bar_white;
  std::vector<PaperText> labels;  ///< title, scale, scale bar figures
  HiddenLineResult stats;         ///< the projected result, before layout
};

/// Draws a view: remove_hidden_lines, then the page. Orthographic views at 1:scale with a
/// scale bar; perspective views on a 270 mm wide page framed by the camera's field of view
/// (aspect 3:2), lines clipped to the frame.
/// @pre options.scale in [1, 10000] (check_floor_plan_options's rule)
/// @param[in] title  the drawing's title line (view and plan name)
[[nodiscard]] LineDrawing draw_line_view(const Model& model, const LineView& view,
                                         const LineDrawingOptions& options,
                                         const std::string& title);

}  // namespace roomcad
