// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_openings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

/// How an item lies against a wall it is parallel to and within reach of.
struct Fit {
  double centre_u = 0.0;  ///< the item's centre projected on the wall, from `from`
  double across = 0.0;    ///< distance from the item's centre to the wall's centre line
  double length = 0.0;    ///< the wall's length
  double way = 1.0;       ///< +1 if the item's width axis runs from -> to, else -1
};

std::optional<Fit> fit_item(const ItemRecord& item, const Wall& w, const HostOptions& options) {
  const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
  if (length == 0) return std::nullopt;
  const Point2 along{(w.to.x - w.from.x) / length, (w.to.y - w.from.y) / length};
  const Point2 axis{std::cos(item.angle), std::sin(item.angle)};
  const double max_sin = std::sin(options.max_angle_deg * std::numbers::pi / 180);
  if (std::abs(axis.x * along.y - axis.y * along.x) > max_sin) return std::nullopt;
  const Point2 rel{item.centre.x - w.from.x, item.centre.y - w.from.y};
  const double across = std::abs(rel.y * along.x - rel.x * along.y);
  if (across > w.thickness / 2 + item.depth / 2 + options.slack) return std::nullopt;
  return Fit{rel.x * along.x + rel.y * along.y, across, length,
             axis.x * along.x + axis.y * along.y >= 0 ? 1.0 : -1.0};
}

/// The item's cut-out along the wall; its wall part starts `wall_left` into its width.
Interval span_along(const ItemRecord& item, const Fit& fit) {
  const double a = -item.width / 2 + item.wall_left * item.width;
  const double b = a + item.wall_width * item.width;
  const double u0 = fit.centre_u + fit.way * a;
  const double u1 = fit.centre_u + fit.way * b;
  return {std::min(u0, u1), std::max(u0, u1)};
}

/// The item's cut-out heights (absolute z); its wall part ends `wall_top` below its top.
/// Its floor is placed like a wall base, so a door on the lowest level starts exactly there.
Interval span_up(const Home& home, const ItemRecord& item, double z_shift_cm) {
  const LevelBase level = level_base(home, item.level);
  const double floor = z_of(level.base_cm + level.floor_offset_cm + z_shift_cm);
  const double top = floor + item.elevation + item.height * (1 - item.wall_top);
  return {top - item.wall_height * item.height, top};
}

bool contains_door(std::string text) {
  std::ranges::transform(text, text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text.find("door") != std::string::npos;
}

/// The part of the cut-out box that lies in wall `w`, or nullopt if it is thinner than
/// `min_piece` either way. Its edges are put on the dyadic grid, where `offset + width` and
/// `sill + height` are exact: openings drawn side by side (touching in decimal, overlapping by
/// 1e-15 m once projected in floating point) touch exactly, and the comparisons with the wall's
/// length and height that validation makes exactly hold.
std::optional<Opening> cut_piece(const ItemRecord& item, const Fit& fit, Interval z,
                                 const Wall& w, double min_piece) {
  const Interval u = span_along(item, fit);
  const double lo = on_dyadic_grid(u.lo < 0 ? kInset : u.lo);
  const double hi = on_dyadic_grid(std::min(u.hi, fit.length - kInset));
  const double v0 = on_dyadic_grid(std::max(z.lo - w.base, 0.0));
  const double v1 = std::min(on_dyadic_grid(z.hi - w.base), w.height);  // on the grid too
  if (hi - lo < min_piece || v1 - v0 < min_piece) return std::nullopt;
  Opening o;
  o.type = classify_item(item);
  o.wall = w.id;
  o.offset = lo;
  o.width = hi - lo;
  o.sill = v0;
  o.height = v1 - v0;
  // The hinge is on the item's left (seen along its width axis) unless mirrored; the wall's
  // `left` is its `from` end, which is the item's left when both axes run the same way.
  const bool hinge_on_item_left = item.sash_on_left != item.mirrored;
  o.hinge = hinge_on_item_left == (fit.way > 0) ? Hinge::left : Hinge::right;
  // A sash opens toward the item's front, which lies to the right of its width axis (its hinge
  // axis sits on the front face of the part in the wall): `in` (the wall's left side) when the
  // item faces against the wall's direction.
  if (item.has_sash) o.swing = fit.way > 0 ? Swing::out : Swing::in;
  return o;
}

/// The pieces of one item: on its host first, then on every other wall it passes through.
std::vector<Opening> cut_item(const Home& home, const ItemRecord& item, const std::string& id,
                              std::size_t host, const std::vector<PlacedWall>& walls,
                              double z_shift_cm) {
  const HostOptions options;
  const Interval z = span_up(home, item, z_shift_cm);
  std::vector<Opening> pieces;
  auto cut = [&](std::size_t i) {
    const std::optional<Fit> fit = fit_item(item, walls[i].wall, options);
    if (!fit) return;
    std::optional<Opening> piece = cut_piece(item, *fit, z, walls[i].wall, options.min_piece);
    if (!piece) return;
    piece->id = pieces.empty() ? id : fmt::format("{}-{}", id, pieces.size() + 1);
    pieces.push_back(std::move(*piece));
  };
  cut(host);
  for (std::size_t i = 0; i < walls.size(); ++i)
    if (i != host) cut(i);
  return pieces;
}

void warn_about_item(const ItemRecord& item, const std::string& id,
                     const std::vector<Opening>& pieces, Report& warnings) {
  const std::string what = fmt::format("{} '{}' ({})", to_string(classify_item(item)), id,
                                       item.name);
  if (pieces.empty()) {
    warnings.add(import_warning(
        Code::import_skipped_opening, id,
        fmt::format("{} at ({:.3f}, {:.3f}) lies in no straight wall of its level parallel to "
                    "it; it is left out",
                    what, item.centre.x, item.centre.y)));
    return;
  }
  if (!item.cut_out_shape.empty() && item.cut_out_shape != kRectangle)
    warnings.add(import_warning(
        Code::import_cut_out_shape, id,
        fmt::format("{} has the cut-out shape '{}'; it is imported as its bounding rectangle",
                    what, item.cut_out_shape)));
  if (pieces.size() > 1) {
    std::vector<std::string> where;
    for (const Opening& o : pieces) where.push_back(fmt::format("'{}' in wall '{}'", o.id, o.wall));
    warnings.add(import_warning(
        Code::import_split_opening, id,
        fmt::format("{} passes through {} walls; it is cut as {}", what, pieces.size(),
                    fmt::join(where, ", "))));
  }
}

}  // namespace

std::optional<std::size_t> find_host_wall(const ItemRecord& item,
                                          const std::vector<PlacedWall>& walls,
                                          const HostOptions& options) {
  std::optional<std::size_t> best;
  std::pair<bool, double> best_score;  // (sticks out of the wall, distance): less is better
  for (std::size_t i = 0; i < walls.size(); ++i) {
    if (walls[i].level != item.level) continue;
    const std::optional<Fit> fit = fit_item(item, walls[i].wall, options);
    if (!fit || fit->centre_u < 0 || fit->centre_u > fit->length) continue;
    const Interval u = span_along(item, *fit);
    const std::pair<bool, double> score{u.lo < 0 || u.hi > fit->length, fit->across};
    if (!best || score < best_score) {
      best = i;
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

std::vector<Opening> place_openings(const Home& home, const std::vector<ItemRecord>& items,
                                    const std::vector<PlacedWall>& walls, double z_shift_cm,
                                    Report& warnings) {
  std::vector<Opening> openings;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const ItemRecord& item = items[k];
    const std::string id = item.id.empty() ? fmt::format("opening{}", k + 1) : item.id;
    const std::optional<std::size_t> host = find_host_wall(item, walls);
    std::vector<Opening> pieces;
    if (host) pieces = cut_item(home, item, id, *host, walls, z_shift_cm);
    warn_about_item(item, id, pieces, warnings);
    std::ranges::move(pieces, std::back_inserter(openings));
  }
  return openings;
}

}  // namespace roomcad::sh3d
