// SPDX-License-Identifier: GPL-3.0-or-later
// The five-cell scale bar of drawings.
#include "render/detail/scale_bar.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace roomcad::detail {

void add_scale_bar(double width, double height, double mm_per_m, ScaleBarOut out) {
  const Point2 origin{kSheetMarginMm, height - kSheetFooterMm};
  const double room_mm = std::max(40.0, 0.35 * (width - 2.0 * kSheetMarginMm));
  constexpr std::array kLengths{0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0};
  double metres = kLengths.front();
  for (const double l : kLengths) {
    if (l * mm_per_m <= room_mm) metres = l;
  }
  const double cell = metres * mm_per_m / 5.0;
  constexpr double kHeight = 2.0;
  for (int i = 0; i < 5; ++i) {
    const double x = origin.x + i * cell;
    PaperPolygon rect{{x, origin.y},
                      {x + cell, origin.y},
                      {x + cell, origin.y + kHeight},
                      {x, origin.y + kHeight}};
    (i % 2 == 0 ? out.black : out.white).push_back(std::move(rect));
  }
  const double baseline = origin.y + kHeight + 4.0;
  out.labels.push_back({{origin.x, baseline}, "0", 2.5, 0.0, TextAnchor::middle});
  out.labels.push_back(
      {{origin.x + 5 * cell, baseline}, fmt::format("{} m", metres), 2.5, 0.0, TextAnchor::middle});
}

}  // namespace roomcad::detail
