// SPDX-License-Identifier: GPL-3.0-or-later
// The architectural floor plan of a Plan: a horizontal section at a cut height, drawn on paper
// at a scale (mm). Pure geometry; io/floor_plan_svg.h writes it as SVG.
//
// Conventions (the plan format leaves the door leaf to drawings): a door's `hinge` is `left`
// when the leaf turns about the opening's end nearer the wall's `from` end (u = offset), and
// `right` at u = offset + width; `swing: in` opens the leaf to the wall's left side (the side
// of its normal, left of from -> to: the inside of walls drawn counter-clockwise), `out` to its
// right side.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad {

/// A finding marked on the plan (`draw --findings`): its label (the code) and its place, a
/// point or a box, metres.
struct PlanMark {
  std::string label;
  Point2 min;
  std::optional<Point2> max;  ///< unset: a point
};

struct FloorPlanOptions {
  double scale = 50.0;      ///< the scale's denominator: 50 means 1:50
  double cut_height = 1.0;  ///< height of the horizontal section above the floor, metres
  /// Findings to mark in red, in order. ({}: a member with an initializer may be left out of
  /// designated initializers such as {.scale = 50} without a warning.)
  std::vector<PlanMark> marks{};
};

/// A straight line on paper, mm, y growing downwards.
struct PaperLine {
  Point2 a;
  Point2 b;
};

/// A circular arc on paper, less than half a turn, from `from` to `to` about `centre`.
struct PaperArc {
  Point2 centre;
  Point2 from;
  Point2 to;
  double radius = 0.0;
};

enum class TextAnchor { start, middle, end };

struct PaperText {
  Point2 at;  ///< the anchor point on the baseline
  std::string text;
  double size = 3.0;        ///< mm
  double rotate_deg = 0.0;  ///< clockwise on paper
  TextAnchor anchor = TextAnchor::middle;
};

using PaperPolygon = std::vector<Point2>;

/// Everything the floor plan shows, in paper millimetres.
struct FloorPlanDrawing {
  double width = 0.0;                      ///< page width, mm
  double height = 0.0;                     ///< page height, mm
  std::vector<PaperPolygon> rooms;         ///< room outlines (a light floor tint)
  std::vector<PaperPolygon> cut_walls;     ///< wall parts the section cuts (filled)
  std::vector<PaperPolygon> walls_below;   ///< walls wholly below the cut (seen, outlined)
  std::vector<PaperPolygon> walls_above;   ///< walls wholly above it (overhead, dashed)
  std::vector<PaperLine> windows;          ///< three lines along the wall per cut window
  std::vector<PaperLine> door_leaves;      ///< each door's leaf, open at 90 degrees
  std::vector<PaperArc> door_swings;       ///< the quarter circle its free edge sweeps
  std::vector<PaperLine> dimension_lines;  ///< extension and dimension lines, end ticks
  std::vector<PaperText> dimension_texts;
  std::vector<PaperText> room_labels;         ///< name, then area, per room
  std::vector<PaperPolygon> scale_bar_black;  ///< filled cells of the scale bar
  std::vector<PaperPolygon> scale_bar_white;  ///< outlined cells
  std::vector<PaperText> labels;              ///< scale bar figures and the title
  /// The map back to the plan (for drawings at true size, io/floor_plan_dxf.h): the plan point
  /// (x, y) metres is at paper (origin.x + x * mm_per_m, origin.y - y * mm_per_m).
  double mm_per_m = 20.0;
  Point2 origin{};
  std::vector<PaperPolygon> marks;     ///< a box round each marked finding (red)
  std::vector<PaperText> mark_labels;  ///< its code, at the box's top-left corner (red)
};

/// Checks the options. @return success, or a usage_error naming the option and its value.
[[nodiscard]] Status check_floor_plan_options(const FloorPlanOptions& options);

/// Draws the floor plan of a plan.
/// @param[in] plan  a plan that validates without errors (roomcad validate)
/// @pre check_floor_plan_options(options).ok() && validate(plan).ok()
/// @return the drawing; a plan with no walls gives a page with the title only. Deterministic.
///   Cost O(n log n) in walls and openings plus find_rooms.
/// @throws PreconditionError (usage_error) if the options are wrong.
[[nodiscard]] FloorPlanDrawing draw_floor_plan(const Plan& plan, const FloorPlanOptions& options);

}  // namespace roomcad
