// SPDX-License-Identifier: GPL-3.0-or-later
// Depth formats against depth error (a report driver, not a timed test): for the perspective
// camera's near plane (render/camera.h kPerspectiveNear, infinite far plane), the step between
// neighbouring stored depths at 1 m, 100 m and 1 km, in metres, for the format the renderer
// uses (reversed-Z float) and the usual alternatives. Two surfaces closer than a step can tie
// or swap: the step is the depth error. Prints CSV: format,distance_m,step_m.
//   depth_format_bench
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "render/camera.h"

namespace {

constexpr double kNear = roomcad::kPerspectiveNear;

/// A depth format: the stored value for a distance, the next stored value towards the far
/// plane, and the distance a stored value stands for.
struct Format {
  const char* name;
  double (*store)(double distance);
  double (*farther)(double stored);
  double (*distance)(double stored);
};

double next_float_down(double z) { return std::nextafter(static_cast<float>(z), 0.0f); }
double next_float_up(double z) { return std::nextafter(static_cast<float>(z), 2.0f); }

/// Fixed point with `bits` bits in [0, 1], standard Z (0 near, 1 at infinity).
template <int bits>
double fixed_store(double d) {
  const double scale = std::ldexp(1.0, bits) - 1.0;
  return std::round((1.0 - kNear / d) * scale) / scale;
}
template <int bits>
double fixed_farther(double z) {
  return z + 1.0 / (std::ldexp(1.0, bits) - 1.0);
}

const Format kFormats[] = {
    {"float32 reversed-Z (roomcad)",
     [](double d) -> double { return static_cast<float>(kNear / d); }, next_float_down,
     [](double z) { return kNear / z; }},
    {"float32 standard Z", [](double d) -> double { return static_cast<float>(1.0 - kNear / d); },
     next_float_up, [](double z) { return kNear / (1.0 - z); }},
    {"fixed 24-bit standard Z", fixed_store<24>, fixed_farther<24>,
     [](double z) { return kNear / (1.0 - z); }},
    {"fixed 16-bit standard Z", fixed_store<16>, fixed_farther<16>,
     [](double z) { return kNear / (1.0 - z); }},
    {"float32 linear distance", [](double d) -> double { return static_cast<float>(d); },
     next_float_up, [](double z) { return z; }},
};

}  // namespace

int main() {
  std::printf("format,distance_m,step_m\n");
  for (const Format& f : kFormats)
    for (const double d : {1.0, 100.0, 1000.0}) {
      const double z = f.store(d);
      const double step = std::abs(f.distance(f.farther(z)) - f.distance(z));
      std::printf("%s,%g,%.3g\n", f.name, d,
                  std::isfinite(step) ? step : std::numeric_limits<double>::infinity());
    }
  return 0;
}
