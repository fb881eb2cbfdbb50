// SPDX-License-Identifier: GPL-3.0-or-later
// Floor plans as SVG: line weights and fills in the architectural manner.
#include "io/floor_plan_svg.h"

#include <span>

namespace roomcad {
namespace {

constexpr double kThin = 0.18;     // mm: dimensions, swings, things seen below the cut
constexpr double kMedium = 0.25;   // windows
constexpr double kThick = 0.5;     // door leaves
constexpr double kOutline = 0.35;  // visible edges of elevations and views
constexpr const char* kFindingRed = "#d00000";

std::string_view anchor_name(TextAnchor anchor) {
  switch (anchor) {
    case TextAnchor::start: return "start";
    case TextAnchor::end: return "end";
    default: return "middle";
  }
}

void add_polygons(SvgDocument& doc, std::string_view id, std::span<const PaperPolygon> polygons,
                  const SvgStyle& style) {
  doc.begin_group(id, id, style);
  for (const PaperPolygon& p : polygons) doc.add_polygon(p);
  doc.end_group();
}

void add_lines(SvgDocument& doc, std::span<const PaperLine> lines) {
  for (const PaperLine& l : lines) doc.add_line(l.a, l.b);
}

void add_line_group(SvgDocument& doc, std::string_view id, std::span<const PaperLine> lines,
                    const SvgStyle& style) {
  doc.begin_group(id, id, style);
  add_lines(doc, lines);
  doc.end_group();
}

void add_scale_bar(SvgDocument& doc, std::span<const PaperPolygon> black,
                   std::span<const PaperPolygon> white) {
  add_polygons(doc, "scale-bar", black, {.fill = "#000"});
  add_polygons(doc, "scale-bar-white", white,
               {.stroke = "#000", .stroke_width = kThin, .fill = "#fff"});
}

void add_texts(SvgDocument& doc, std::string_view id, std::span<const PaperText> texts,
               const std::string& fill = "#000") {
  doc.begin_group(id, id);
  for (const PaperText& t : texts) {
    doc.add_text(t.at, t.text,
                 {.size = t.size,
                  .anchor = std::string(anchor_name(t.anchor)),
                  .fill = fill,
                  .rotate_deg = t.rotate_deg});
  }
  doc.end_group();
}

void add_doors(SvgDocument& doc, const FloorPlanDrawing& d) {
  doc.begin_group("doors", "doors", {.stroke = "#000", .fill = "none"});
  doc.begin_group("", "leaves", {.stroke_width = kThick});
  add_lines(doc, d.door_leaves);
  doc.end_group();
  doc.begin_group("", "swings", {.stroke_width = kThin});
  for (const PaperArc& arc : d.door_swings) {
    const Point2 a{arc.from.x - arc.centre.x, arc.from.y - arc.centre.y};
    const Point2 b{arc.to.x - arc.centre.x, arc.to.y - arc.centre.y};
    // SVG's sweep flag 1 turns the way of positive angles in its y-down frame.
    const bool sweep = a.x * b.y - a.y * b.x > 0.0;
    doc.add_path(
        SvgPath().move_to(arc.from).arc_to(arc.radius, arc.radius, 0, false, sweep, arc.to));
  }
  doc.end_group();
  doc.end_group();
}

}  // namespace

SvgDocument make_floor_plan_svg(const FloorPlanDrawing& d, const std::string& title) {
  SvgDocument doc(d.width, d.height);
  if (!title.empty()) doc.set_title(title);
  doc.add_rect({0, 0}, d.width, d.height, {.fill = "#fff"});
  add_polygons(doc, "rooms", d.rooms, {.fill = "#f3efe6"});
  add_polygons(doc, "walls-below", d.walls_below,
               {.stroke = "#000", .stroke_width = kThin, .fill = "none"});
  add_polygons(doc, "walls-above", d.walls_above,
               {.stroke = "#000", .stroke_width = kThin, .fill = "none", .dashes = {2, 1}});
  add_polygons(doc, "cut-walls", d.cut_walls, {.fill = "#1a1a1a"});
  add_line_group(doc, "windows", d.windows, {.stroke = "#000", .stroke_width = kMedium});
  add_doors(doc, d);
  add_line_group(doc, "dimensions", d.dimension_lines, {.stroke = "#000", .stroke_width = kThin});
  add_texts(doc, "dimension-texts", d.dimension_texts);
  add_texts(doc, "room-labels", d.room_labels);
  add_scale_bar(doc, d.scale_bar_black, d.scale_bar_white);
  add_texts(doc, "labels", d.labels);
  if (!d.marks.empty()) {  // findings, over everything else
    add_polygons(doc, "findings", d.marks,
                 {.stroke = kFindingRed, .stroke_width = kMedium, .fill = "none"});
    add_texts(doc, "finding-codes", d.mark_labels, kFindingRed);
  }
  return doc;
}

SvgDocument make_line_drawing_svg(const LineDrawing& d, const std::string& title) {
  SvgDocument doc(d.width, d.height);
  if (!title.empty()) doc.set_title(title);
  doc.add_rect({0, 0}, d.width, d.height, {.fill = "#fff"});
  add_line_group(
      doc, "hidden", d.hidden,
      {.stroke = "#000", .stroke_width = kThin, .dashes = {1.5, 1.0}, .linecap = "butt"});
  add_line_group(doc, "visible", d.visible,
                 {.stroke = "#000", .stroke_width = kOutline, .linecap = "round"});
  add_line_group(doc, "frame", d.frame, {.stroke = "#000", .stroke_width = kThin});
  add_scale_bar(doc, d.scale_bar_black, d.scale_bar_white);
  add_texts(doc, "labels", d.labels);
  return doc;
}

}  // namespace roomcad
