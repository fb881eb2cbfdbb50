// SPDX-License-Identifier: GPL-3.0-or-later
// The floor plan's page: layout at the scale, walls, rooms, dimensions, scale bar and title.
#include "render/floor_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "core/box.h"
#include "geometry/rooms.h"
#include "render/detail/plan_paper.h"
#include "render/detail/scale_bar.h"

namespace roomcad {
namespace {

using detail::kSheetFooterMm;
using detail::kSheetMarginMm;
using detail::PaperMap;
using detail::operator+;
using detail::operator-;
using detail::operator*;

constexpr double kWallDimensionMm = 5.0;  // per-wall dimension beyond the wall face
constexpr double kOverallDimensionMm = 18.0;
constexpr double kMarkMm = 2.0;      // half the side of a point finding's box; a box's margin
constexpr double kMarkTextMm = 2.5;  // size of a finding's code

/// The extent of the wall footprints, or of the site when there are no walls.
Box2 plan_extent(const Plan& plan, const Joins& joins) {
  Box2 box = empty_box2();
  for (std::size_t i = 0; i < plan.walls.size(); ++i) {
    const Wall& w = plan.walls[i];
    if (!(detail::length(w.to - w.from) > 0.0 && w.thickness > 0.0)) continue;
    for (const Point2& p : wall_footprint(plan, joins, i)) add_point(box, p.x, p.y);
  }
  if (is_empty(box)) {
    const Site& s = plan.site;
    add_point(box, s.origin.x, s.origin.y);
    add_point(box, s.origin.x + s.cells[0] * s.cell_size, s.origin.y + s.cells[1] * s.cell_size);
  }
  return box;
}

/// @return the area centroid of a polygon (its first vertex if it has no area).
Point2 centroid(const std::vector<Point2>& outline) {
  double a2 = 0.0;
  Point2 c{0.0, 0.0};
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Point2 p = outline[k];
    const Point2 q = outline[(k + 1) % outline.size()];
    const double w = detail::cross(p, q);
    a2 += w;
    c = c + (w / 3.0) * (p + q);
  }
  return a2 != 0.0 ? (1.0 / a2) * c : outline.front();
}

/// Dimensions each wall on its outer side: away from the rooms it bounds, or from the plan's
/// centre if it bounds none. Partitions with rooms on both sides are left to the room sizes.
void add_wall_dimensions(const Plan& plan, const std::vector<Room>& rooms, Point2 centre,
                         const PaperMap& map, FloorPlanDrawing& out) {
  for (const Wall& w : plan.walls) {
    const Point2 along = w.to - w.from;
    if (!(detail::length(along) > 0.0)) continue;
    const Point2 left = detail::left_normal(along);
    bool rooms_left = false;
    bool rooms_right = false;
    for (const Room& room : rooms) {
      if (std::find(room.walls.begin(), room.walls.end(), w.id) == room.walls.end()) continue;
      (detail::dot(left, centroid(room.outline) - w.from) > 0.0 ? rooms_left : rooms_right) = true;
    }
    if (rooms_left && rooms_right) continue;
    Point2 side = rooms_left ? -1.0 * left : left;
    if (!rooms_left && !rooms_right && detail::dot(side, 0.5 * (w.from + w.to) - centre) < 0.0) {
      side = -1.0 * side;
    }
    detail::add_dimension(w.from, w.to, side, 0.5 * w.thickness * map.mm_per_m + kWallDimensionMm,
                          map, out);
  }
}

void add_rooms(const std::vector<Room>& rooms, const PaperMap& map, FloorPlanDrawing& out) {
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const Room& room = rooms[i];
    if (room.outline.size() < 3) continue;
    out.rooms.push_back(map.to_paper(room.outline));
    const Point2 at = map.to_paper(centroid(room.outline));
    out.room_labels.push_back({at, fmt::format("Room {}", i + 1), 3.5, 0.0, TextAnchor::middle});
    out.room_labels.push_back({at + Point2{0.0, 4.5},
                               fmt::format("{} m²", detail::format_metres(room.area)), 3.0, 0.0,
                               TextAnchor::middle});
  }
}

/// Boxes round the marked findings and their codes above them; codes marked at one corner
/// are stacked, so that each can be read.
void add_marks(const std::vector<PlanMark>& marks, const PaperMap& map, FloorPlanDrawing& out) {
  std::vector<std::pair<Point2, int>> corners;  // top-left corners used, with their labels
  for (const PlanMark& m : marks) {
    const Point2 a = map.to_paper(m.min), b = map.to_paper(m.max.value_or(m.min));
    const Point2 lo{std::min(a.x, b.x) - kMarkMm, std::min(a.y, b.y) - kMarkMm};
    const Point2 hi{std::max(a.x, b.x) + kMarkMm, std::max(a.y, b.y) + kMarkMm};
    out.marks.push_back({lo, {hi.x, lo.y}, hi, {lo.x, hi.y}});
    auto it = std::find_if(corners.begin(), corners.end(), [&](const auto& c) {
      return std::abs(c.first.x - lo.x) < kMarkTextMm && std::abs(c.first.y - lo.y) < kMarkTextMm;
    });
    if (it == corners.end()) it = corners.insert(corners.end(), {lo, 0});
    out.mark_labels.push_back({{lo.x, lo.y - 0.8 - kMarkTextMm * 1.2 * it->second++},
                               m.label,
                               kMarkTextMm,
                               0.0,
                               TextAnchor::start});
  }
}

/// Calls f(point, pad) for every point of the drawing; `pad` is how far the element reaches
/// around it (a text's size, an arc's radius), 0 for plain vertices.
template <class Drawing, class F>
void for_each_point(Drawing& d, F f) {
  for (auto* polygons : {&d.rooms, &d.cut_walls, &d.walls_below, &d.walls_above, &d.scale_bar_black,
                         &d.scale_bar_white, &d.marks}) {
    for (auto& polygon : *polygons) {
      for (auto& p : polygon) f(p, 0.0);
    }
  }
  for (auto* lines : {&d.windows, &d.door_leaves, &d.dimension_lines}) {
    for (auto& line : *lines) f(line.a, 0.0), f(line.b, 0.0);
  }
  for (auto& arc : d.door_swings) f(arc.centre, arc.radius), f(arc.from, 0.0), f(arc.to, 0.0);
  for (auto* texts : {&d.dimension_texts, &d.room_labels, &d.labels, &d.mark_labels}) {
    for (auto& text : *texts) f(text.at, text.size);
  }
}

/// Moves everything drawn so that it starts kSheetMarginMm from the top-left corner, and sizes
/// the page to it plus the footer: door swings and dimensions reach beyond the walls.
void fit_page(FloorPlanDrawing& d) {
  Box2 box = empty_box2();
  for_each_point(std::as_const(d), [&box](const Point2& p, double pad) {
    add_point(box, p.x - pad, p.y - pad);
    add_point(box, p.x + pad, p.y + pad);
  });
  if (is_empty(box)) add_point(box, 0.0, 0.0);
  const Point2 shift{kSheetMarginMm - box.min_x, kSheetMarginMm - box.min_y};
  for_each_point(d, [shift](Point2& p, double) { p = p + shift; });
  d.origin = d.origin + shift;
  d.width = box.max_x - box.min_x + 2.0 * kSheetMarginMm;
  d.height = box.max_y - box.min_y + 2.0 * kSheetMarginMm + kSheetFooterMm;
}

}  // namespace

Status check_floor_plan_options(const FloorPlanOptions& o) {
  if (!(o.scale >= 1.0 && o.scale <= 10000.0)) {
    return Status::failure(Code::usage_error,
                           fmt::format("scale 1:{} is not between 1:1 and 1:10000", o.scale));
  }
  if (!(std::isfinite(o.cut_height) && o.cut_height > 0.0)) {
    return Status::failure(
        Code::usage_error,
        fmt::format("cut height must be a positive number of metres, got {}", o.cut_height));
  }
  return Status::success();
}

FloorPlanDrawing draw_floor_plan(const Plan& plan, const FloorPlanOptions& options) {
  throw_if_failed(check_floor_plan_options(options), "draw_floor_plan");
  const Joins joins = find_joins(plan);
  const Box2 box = plan_extent(plan, joins);
  // Placed anywhere for now: fit_page moves everything onto the page once it is all drawn.
  const PaperMap map{.mm_per_m = 1000.0 / options.scale, .x_min = box.min_x, .y_max = box.max_y};
  FloorPlanDrawing out;
  out.mm_per_m = map.mm_per_m;
  out.origin = map.to_paper({0.0, 0.0});
  const std::vector<Room> rooms = find_rooms(plan);
  add_rooms(rooms, map, out);
  detail::draw_plan_walls(plan, joins, options, map, out);
  add_wall_dimensions(plan, rooms, {0.5 * (box.min_x + box.max_x), 0.5 * (box.min_y + box.max_y)},
                      map, out);
  if (!plan.walls.empty()) {
    detail::add_dimension({box.min_x, box.min_y}, {box.max_x, box.min_y}, {0.0, -1.0},
                          kOverallDimensionMm, map, out);
    detail::add_dimension({box.min_x, box.min_y}, {box.min_x, box.max_y}, {-1.0, 0.0},
                          kOverallDimensionMm, map, out);
  }
  add_marks(options.marks, map, out);
  fit_page(out);
  const double footer = out.height - kSheetFooterMm;
  detail::add_scale_bar(out.width, out.height, map.mm_per_m,
                        {out.scale_bar_black, out.scale_bar_white, out.labels});
  out.labels.push_back(
      {{kSheetMarginMm, footer + 16.0},
       fmt::format("Floor plan, section at {:.2f} m, scale 1:{}, dimensions in metres",
                   options.cut_height, options.scale),
       3.5,
       0.0,
       TextAnchor::start});
  return out;
}

}  // namespace roomcad
