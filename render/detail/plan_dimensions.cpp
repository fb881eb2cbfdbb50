// SPDX-License-Identifier: GPL-3.0-or-later
// Dimension lines in the architectural manner: extension lines with a small gap at the
// object, a dimension line, 45-degree ticks at its ends and the length above it.
#include <fmt/format.h>

#include "render/detail/plan_paper.h"

namespace roomcad::detail {
namespace {

constexpr double kGapMm = 1.0;        // between the object and its extension line
constexpr double kOvershootMm = 1.5;  // extension line beyond the dimension line
constexpr double kTickMm = 1.2;       // half-length of the end ticks
constexpr double kTextSizeMm = 2.5;
constexpr double kTextLiftMm = 1.0;  // text baseline above the dimension line

}  // namespace

std::string format_metres(double metres) { return fmt::format("{:.2f}", metres); }

void add_dimension(Point2 a, Point2 b, Point2 side, double offset_mm, const PaperMap& map,
                   FloorPlanDrawing& out) {
  const Point2 pa = map.to_paper(a);
  const Point2 pb = map.to_paper(b);
  const Point2 along = pb - pa;
  const double len = length(along);
  if (!(len > 0.0)) return;
  const Point2 u = (1.0 / len) * along;
  // The side in plan terms, turned into paper (y flips), then made perpendicular to the line.
  Point2 normal = left_normal(u);
  if (dot(normal, Point2{side.x, -side.y}) < 0.0) normal = -1.0 * normal;
  const Point2 da = pa + offset_mm * normal;
  const Point2 db = pb + offset_mm * normal;
  out.dimension_lines.push_back({pa + kGapMm * normal, da + kOvershootMm * normal});
  out.dimension_lines.push_back({pb + kGapMm * normal, db + kOvershootMm * normal});
  out.dimension_lines.push_back({da, db});
  const Point2 tick = kTickMm * ((1.0 / std::sqrt(2.0)) * (u + normal));
  out.dimension_lines.push_back({da - tick, da + tick});
  out.dimension_lines.push_back({db - tick, db + tick});
  // Keep the text readable from the bottom or the right of the sheet: the angle in [-90, 90),
  // so vertical texts read bottom to top.
  double angle = std::atan2(u.y, u.x) * 180.0 / M_PI;
  if (angle >= 90.0) angle -= 180.0;
  if (angle < -90.0) angle += 180.0;
  const Point2 mid = 0.5 * (da + db);
  const double rad = angle * M_PI / 180.0;
  const Point2 up{std::sin(rad), -std::cos(rad)};  // the text's "up" on paper
  out.dimension_texts.push_back({mid + kTextLiftMm * up, format_metres(length(b - a)), kTextSizeMm,
                                 angle, TextAnchor::middle});
}

}  // namespace roomcad::detail
