// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_openings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "import/detail/sh3d_cut_out.h"
#include "plan/plan_chords.h"
#include "plan/signed_area.h"

namespace roomcad::sh3d {
namespace {

constexpr std::string_view kRectangle = "M0,0 v1 h1 v-1 z";  // Sweet Home 3D's plain cut-out
// A piece clipped at a wall's end stops this far inside it, so that it stays inside the wall
// whatever the rounding of the wall's length; far below any drawn detail.
constexpr double kInset = 1e-6;

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

/// One straight piece of a wall's centre line (a whole straight wall, or a chord of an arc).
struct Segment {
  std::size_t wall = 0;  ///< index into the placed walls
  Point2 from;
  Point2 to;
  double start = 0.0;  ///< metres along the wall's polyline where it starts
  double total = 0.0;  ///< the wall's polyline length
};

std::vector<Segment> segments_of(const std::vector<PlacedWall>& walls) {
  std::vector<Segment> segments;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const std::vector<Point2>& line = walls[w].polyline;
    const double total = polyline_length(line);
    double start = 0.0;
    for (std::size_t k = 1; k < line.size(); ++k) {
      segments.push_back({w, line[k - 1], line[k], start, total});
      start += std::hypot(line[k].x - line[k - 1].x, line[k].y - line[k - 1].y);
    }
  }
  return segments;
}

/// How an item lies against a wall it is parallel to and within reach of.
struct Fit {
  double centre_u = 0.0;  ///< the item's centre projected on the wall, from its start
  double across = 0.0;    ///< distance from the item's centre to the wall's centre line
  double length = 0.0;    ///< the wall's length (along its polyline)
  double way = 1.0;       ///< +1 if the item's width axis runs from -> to, else -1
  bool over = false;      ///< the centre projects onto this segment of the wall
};

std::optional<Fit> fit_item(const ItemRecord& item, const Segment& s, double thickness,
                            const HostOptions& options) {
  const double length = std::hypot(s.to.x - s.from.x, s.to.y - s.from.y);
  if (length == 0) return std::nullopt;
  const Point2 along{(s.to.x - s.from.x) / length, (s.to.y - s.from.y) / length};
  const Point2 axis{std::cos(item.angle), std::sin(item.angle)};
  const double max_sin = std::sin(options.max_angle_deg * std::numbers::pi / 180);
  if (std::abs(axis.x * along.y - axis.y * along.x) > max_sin) return std::nullopt;
  const Point2 rel{item.centre.x - s.from.x, item.centre.y - s.from.y};
  const double across = std::abs(rel.y * along.x - rel.x * along.y);
  if (across > thickness / 2 + item.depth / 2 + options.slack) return std::nullopt;
  const double u = rel.x * along.x + rel.y * along.y;
  return Fit{s.start + u, across, s.total, axis.x * along.x + axis.y * along.y >= 0 ? 1.0 : -1.0,
             u >= 0 && u <= length};
}

/// The u (along the wall) of the point `x` of the item's width (0: its left, 1: its right).
double u_of(const ItemRecord& item, const Fit& fit, double x) {
  return fit.centre_u + fit.way * (x - 0.5) * item.width;
}

/// The item's cut-out along the wall; its wall part starts `wall_left` into its width.
Interval span_along(const ItemRecord& item, const Fit& fit) {
  const double u0 = u_of(item, fit, item.wall_left);
  const double u1 = u_of(item, fit, item.wall_left + item.wall_width);
  return {std::min(u0, u1), std::max(u0, u1)};
}

/// The z (metres) of the floor of the item's level, placed like the level's elevation.
double floor_z(const std::vector<PlacedLevel>& levels, const ItemRecord& item, double z_shift_cm) {
  const PlacedLevel* level = find_placed(levels, item.level);
  return level ? level->level.elevation : z_of(z_shift_cm);
}

/// The item's cut-out heights (absolute z); its wall part ends `wall_top` below its top.
Interval span_up(const ItemRecord& item, double floor) {
  const double top = floor + item.elevation + item.height * (1 - item.wall_top);
  return {top - item.wall_height * item.height, top};
}

bool contains_door(std::string text) {
  std::ranges::transform(text, text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text.find("door") != std::string::npos;
}

/// Where one item cuts one wall: the wall, how the item lies against it, the item's outline.
struct Cut {
  const PlacedWall& wall;
  const Fit& fit;
  Interval z;              ///< the item's wall part, absolute heights
  double floor = 0.0;      ///< z of the item's level floor
  const Polygon* outline;  ///< its cut-out in its unit square (v up), or nullptr
};

/// The hole of the cut in the wall's (u, v) frame, clipped to `rect` and under the wall's top
/// (less 10 micrometres, so that no rounded corner pokes above it).
Polygon hole_in_wall(const ItemRecord& item, const Cut& cut, Interval u, Interval v) {
  const Wall& w = cut.wall.wall;
  Polygon hole;
  if (cut.outline) {
    const double bottom = cut.floor + item.elevation - cut.wall.base_z;
    for (const Point2& p : *cut.outline)
      hole.push_back({u_of(item, cut.fit, p.x), bottom + p.y * item.height});
  } else {
    hole = {{u.lo, v.lo}, {u.hi, v.lo}, {u.hi, v.hi}, {u.lo, v.hi}};
  }
  hole = clip_half_plane(hole, -1, 0, -u.lo);
  hole = clip_half_plane(hole, 1, 0, u.hi);
  hole = clip_half_plane(hole, 0, -1, -v.lo);
  hole = clip_half_plane(hole, 0, 1, v.hi);
  if (w.height_at_end) {  // v <= height + slope * u
    const double slope = (*w.height_at_end - w.height) / cut.fit.length;
    hole = clip_half_plane(hole, -slope, 1, w.height - 1e-5);
  }
  return hole;
}

/// The hole in the unit square of the rectangle u x v, rounded to 1e-6, counter-clockwise;
/// empty when it is that whole rectangle.
Polygon unit_shape(const Polygon& hole, Interval u, Interval v) {
  Polygon shape;
  for (const Point2& p : hole) {
    const auto unit = [](double t) { return std::clamp(std::round(t * 1e6) / 1e6, 0.0, 1.0); };
    const Point2 q{unit((p.x - u.lo) / (u.hi - u.lo)), unit((p.y - v.lo) / (v.hi - v.lo))};
    if (shape.empty() || !(shape.back() == q)) shape.push_back(q);
  }
  while (shape.size() > 1 && shape.front() == shape.back()) shape.pop_back();
  if (signed_area(shape) < 0) std::ranges::reverse(shape);
  const Polygon whole{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return shape.size() == 4 &&
                 std::ranges::all_of(
                     shape, [&](Point2 p) { return std::ranges::find(whole, p) != whole.end(); })
             ? Polygon{}
             : shape;
}

/// The part of the cut-out that lies in the wall, or nullopt if it is thinner than
/// `min_piece` either way. Its rectangle's edges are put on the dyadic grid, where
/// `offset + width` and `sill + height` are exact: openings drawn side by side (touching in
/// decimal, overlapping by 1e-15 m once projected in floating point) touch exactly, and the
/// comparisons with the wall's length and height that validation makes exactly hold. Its
/// outline (`shape`) is the item's cut-out shape clipped to the wall and under its top.
std::optional<Opening> cut_piece(const ItemRecord& item, const Cut& cut, double min_piece) {
  const Wall& w = cut.wall.wall;
  const Interval along = span_along(item, cut.fit);
  const Interval u{on_dyadic_grid(along.lo < 0 ? kInset : along.lo),
                   on_dyadic_grid(std::min(along.hi, cut.fit.length - kInset))};
  const double highest = highest_height(w);
  const Interval v{on_dyadic_grid(std::max(cut.z.lo - cut.wall.base_z, 0.0)),
                   std::min(on_dyadic_grid(cut.z.hi - cut.wall.base_z), highest)};
  if (u.hi - u.lo < min_piece || v.hi - v.lo < min_piece) return std::nullopt;
  const Polygon hole = hole_in_wall(item, cut, u, v);
  if (hole.size() < 3 || std::abs(signed_area(hole)) < min_piece * min_piece) return std::nullopt;
  Opening o;
  o.type = classify_item(item);
  o.wall = w.id;
  o.offset = u.lo;
  o.width = u.hi - u.lo;
  o.sill = v.lo;
  o.height = v.hi - v.lo;
  o.shape = unit_shape(hole, u, v);
  // The hinge is on the item's left (seen along its width axis) unless mirrored; the wall's
  // `left` is its `from` end, which is the item's left when both axes run the same way.
  const bool hinge_on_item_left = item.sash_on_left != item.mirrored;
  o.hinge = hinge_on_item_left == (cut.fit.way > 0) ? Hinge::left : Hinge::right;
  // A sash opens toward the item's front, which lies to the right of its width axis (its hinge
  // axis sits on the front face of the part in the wall): `in` (the wall's left side) when the
  // item faces against the wall's direction.
  if (item.has_sash) o.swing = cut.fit.way > 0 ? Swing::out : Swing::in;
  return o;
}

/// The first segment of wall `w` that the item lies against and whose stretch its cut-out
/// reaches (the host segment for the host wall).
std::optional<Fit> fit_wall(const ItemRecord& item, const std::vector<Segment>& segments,
                            const std::vector<PlacedWall>& walls, std::size_t w) {
  const HostOptions options;
  for (const Segment& s : segments) {
    if (s.wall != w) continue;
    const std::optional<Fit> fit = fit_item(item, s, walls[w].wall.thickness, options);
    if (!fit) continue;
    const Interval u = span_along(item, *fit);
    const double seg_length = std::hypot(s.to.x - s.from.x, s.to.y - s.from.y);
    if (fit->over || (u.hi > s.start && u.lo < s.start + seg_length)) return fit;
  }
  return std::nullopt;
}

/// The pieces of one item: on its host first, then on every other wall it passes through.
std::vector<Opening> cut_item(const ItemRecord& item, const std::string& id, const Fit& host_fit,
                              std::size_t host, const std::vector<Segment>& segments,
                              const std::vector<PlacedWall>& walls, const Placement& placement) {
  const double floor = floor_z(placement.levels, item, placement.z_shift_cm);
  const Interval z = span_up(item, floor);
  std::vector<Opening> pieces;
  auto cut = [&](std::size_t i, const Fit& fit) {
    const Cut c{walls[i], fit, z, floor, placement.outline};
    std::optional<Opening> piece = cut_piece(item, c, HostOptions{}.min_piece);
    if (!piece) return;
    piece->id = pieces.empty() ? id : fmt::format("{}-{}", id, pieces.size() + 1);
    pieces.push_back(std::move(*piece));
  };
  cut(host, host_fit);
  for (std::size_t i = 0; i < walls.size(); ++i)
    if (i != host)
      if (const std::optional<Fit> fit = fit_wall(item, segments, walls, i)) cut(i, *fit);
  return pieces;
}

void warn_about_item(const ItemRecord& item, const std::string& id,
                     const std::vector<Opening>& pieces, bool shape_read, Report& warnings) {
  const std::string what =
      fmt::format("{} '{}' ({})", to_string(classify_item(item)), id, item.name);
  if (pieces.empty()) {
    warnings.add(import_warning(
        Code::import_skipped_opening, id,
        fmt::format("{} at ({:.3f}, {:.3f}) lies in no straight wall of its level parallel to "
                    "it; it is left out",
                    what, item.centre.x, item.centre.y)));
    return;
  }
  if (!shape_read)
    warnings.add(import_warning(
        Code::import_cut_out_shape, id,
        fmt::format("{} has the cut-out shape '{}', which is not an SVG path of one closed "
                    "outline that roomcad reads; it is imported as its bounding rectangle",
                    what, item.cut_out_shape)));
  if (pieces.size() > 1) {
    std::vector<std::string> where;
    for (const Opening& o : pieces) where.push_back(fmt::format("'{}' in wall '{}'", o.id, o.wall));
    warnings.add(import_warning(Code::import_split_opening, id,
                                fmt::format("{} passes through {} walls; it is cut as {}", what,
                                            pieces.size(), fmt::join(where, ", "))));
  }
}

}  // namespace

/// Whether an item of level `a` may stand in a wall of level `b`: the same level, or levels
/// at the same elevation (Sweet Home 3D's layers: a door drawn on one cuts the walls of all).
bool same_storey(const std::vector<PlacedLevel>& levels, const std::string& a,
                 const std::string& b) {
  if (a == b) return true;
  const PlacedLevel* la = find_placed(levels, a);
  const PlacedLevel* lb = find_placed(levels, b);
  return la && lb && la->level.elevation == lb->level.elevation;
}

std::optional<std::pair<std::size_t, Fit>> find_host(const ItemRecord& item,
                                                     const std::vector<Segment>& segments,
                                                     const std::vector<PlacedWall>& walls,
                                                     const std::vector<PlacedLevel>& levels,
                                                     const HostOptions& options) {
  std::optional<std::pair<std::size_t, Fit>> best;
  std::pair<bool, double> best_score;  // (sticks out of the wall, distance): less is better
  for (const Segment& s : segments) {
    if (!same_storey(levels, walls[s.wall].level, item.level)) continue;
    const std::optional<Fit> fit = fit_item(item, s, walls[s.wall].wall.thickness, options);
    if (!fit || !fit->over) continue;
    const Interval u = span_along(item, *fit);
    const std::pair<bool, double> score{u.lo < 0 || u.hi > fit->length, fit->across};
    if (!best || score < best_score) {
      best = {s.wall, *fit};
      best_score = score;
    }
  }
  return best;
}

OpeningType classify_item(const ItemRecord& item) {
  if (contains_door(item.name) || contains_door(item.catalog_id)) return OpeningType::door;
  if (item.elevation <= 0.01 && item.height >= 1.8) return OpeningType::door;
  return OpeningType::window;
}

std::vector<Opening> place_openings(const std::vector<ItemRecord>& items,
                                    const std::vector<PlacedWall>& walls,
                                    const Placement& placement, Report& warnings) {
  const std::vector<Segment> segments = segments_of(walls);
  std::vector<Opening> openings;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const ItemRecord& item = items[k];
    const std::string id = item.id.empty() ? fmt::format("opening{}", k + 1) : item.id;
    std::optional<Polygon> outline;
    const bool shaped = !item.cut_out_shape.empty() && item.cut_out_shape != kRectangle;
    if (shaped)
      outline =
          parse_cut_out(item.cut_out_shape, item.width, item.height, placement.chord_tolerance);
    Placement with_outline = placement;
    with_outline.outline = outline ? &*outline : nullptr;
    std::vector<Opening> pieces;
    if (const auto host = find_host(item, segments, walls, placement.levels, HostOptions{}))
      pieces = cut_item(item, id, host->second, host->first, segments, walls, with_outline);
    warn_about_item(item, id, pieces, !shaped || outline.has_value(), warnings);
    std::ranges::move(pieces, std::back_inserter(openings));
  }
  return openings;
}

}  // namespace roomcad::sh3d
