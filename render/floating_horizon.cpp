// SPDX-License-Identifier: GPL-3.0-or-later
// The floating-horizon method: sampling, the window (seed: алгоритм ОКНО) and the sweep over
// the sections from front to back.
#include "render/floating_horizon.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "render/detail/horizon_sweep.h"

namespace roomcad {
namespace {

constexpr double kMaxSamplesPerAxis = 20001;
constexpr double kMaxSamples = 4e6;
constexpr int kMaxColumns = 100000;

/// @return the number of steps that divide `range` evenly with steps no longer than `step`.
double count_steps(double range, double step) {
  return range <= 0.0 ? 0.0 : std::max(1.0, std::ceil(range / step - 1e-9));
}

Status check_view(const SurfaceView& v) {
  for (const auto& [name, value] : {std::pair{"x_min", v.x_min},
                                    {"x_max", v.x_max},
                                    {"z_min", v.z_min},
                                    {"z_max", v.z_max},
                                    {"dx", v.dx},
                                    {"dz", v.dz},
                                    {"rotate_x", v.rotate_x_deg},
                                    {"rotate_y", v.rotate_y_deg}}) {
    if (!std::isfinite(value))
      return Status::failure(Code::usage_error,
                             fmt::format("{} must be a finite number, got {}", name, value));
  }
  if (!(v.x_min < v.x_max))
    return Status::failure(Code::usage_error,
                           fmt::format("x range {}:{} is empty", v.x_min, v.x_max));
  if (!(v.z_min <= v.z_max))
    return Status::failure(Code::usage_error,
                           fmt::format("z range {}:{} is reversed", v.z_min, v.z_max));
  if (!(v.dx > 0.0))
    return Status::failure(Code::usage_error, fmt::format("dx must be positive, got {}", v.dx));
  if (!(v.dz > 0.0))
    return Status::failure(Code::usage_error, fmt::format("dz must be positive, got {}", v.dz));
  for (const auto& [name, value] :
       {std::pair{"rotate_x", v.rotate_x_deg}, {"rotate_y", v.rotate_y_deg}}) {
    if (!(std::fabs(value) < 90.0)) {
      return Status::failure(
          Code::usage_error,
          fmt::format("{} must lie strictly between -90 and 90 degrees, got {}", name, value));
    }
  }
  const double nx = count_steps(v.x_max - v.x_min, v.dx) + 1.0;
  const double nz = count_steps(v.z_max - v.z_min, v.dz) + 1.0;
  if (nx > kMaxSamplesPerAxis || nz > kMaxSamplesPerAxis || nx * nz > kMaxSamples) {
    return Status::failure(
        Code::usage_error,
        fmt::format("dx {} and dz {} give {} x {} samples; at most {} per axis and {} in all", v.dx,
                    v.dz, nx, nz, kMaxSamplesPerAxis, kMaxSamples));
  }
  return Status::success();
}

/// The rotated sample points (picture plane X, Y), NaN where f has no finite value.
struct SampleGrid {
  std::size_t nx = 0;
  std::size_t nz = 0;
  std::vector<ScreenPoint> points;  ///< section j, sample i at j * nx + i
};

SampleGrid sample_surface(const SurfaceFunction& f, const SurfaceView& v) {
  SampleGrid grid;
  const double steps_x = count_steps(v.x_max - v.x_min, v.dx);
  const double steps_z = count_steps(v.z_max - v.z_min, v.dz);
  grid.nx = static_cast<std::size_t>(steps_x) + 1;
  grid.nz = static_cast<std::size_t>(steps_z) + 1;
  grid.points.resize(grid.nx * grid.nz);
  const double ry = v.rotate_y_deg * std::numbers::pi / 180.0;
  const double rx = v.rotate_x_deg * std::numbers::pi / 180.0;
  const double cy = std::cos(ry), sy = std::sin(ry), cx = std::cos(rx), sx = std::sin(rx);
  tbb::parallel_for(std::size_t{0}, grid.nz, [&](std::size_t j) {
    const double z = steps_z == 0.0 ? v.z_min : v.z_min + (v.z_max - v.z_min) * (j / steps_z);
    for (std::size_t i = 0; i < grid.nx; ++i) {
      const double x = v.x_min + (v.x_max - v.x_min) * (i / steps_x);
      const double y = f(x, z);
      const double nan = std::numeric_limits<double>::quiet_NaN();
      // Rotate about y, then about x (the seed's fixed order); the viewer is at z = -inf.
      grid.points[j * grid.nx + i] =
          std::isfinite(y) ? ScreenPoint{x * cy + z * sy, y * cx + (z * cy - x * sy) * sx}
                           : ScreenPoint{nan, nan};
    }
  });
  return grid;
}

/// Fits the finite points into the screen, centred: the seed's window (алгоритм ОКНО).
/// @return false if there is no finite point.
bool fit_window(const SampleGrid& grid, const SurfaceScreen& screen, SurfaceDrawing& out) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const ScreenPoint& p : grid.points) {
    if (std::isnan(p.x)) continue;
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  if (x0 > x1) return false;
  const double room_x = screen.width - 2.0 * screen.margin;
  const double room_y = screen.height - 2.0 * screen.margin;
  // A flat extent (a single point, or a plane seen edge-on) does not limit the scale.
  const double sx = x1 > x0 ? room_x / (x1 - x0) : INFINITY;
  const double sy = y1 > y0 ? room_y / (y1 - y0) : INFINITY;
  const double common = std::isinf(std::min(sx, sy)) ? 1.0 : std::min(sx, sy);
  out.scale_x = screen.keep_aspect || std::isinf(sx) ? common : sx;
  out.scale_y = screen.keep_aspect || std::isinf(sy) ? common : sy;
  out.origin_x = 0.5 * screen.width - out.scale_x * 0.5 * (x0 + x1);
  out.origin_y = 0.5 * screen.height + out.scale_y * 0.5 * (y0 + y1);
  return true;
}

/// Sweeps the sections from front to back through the horizons.
std::vector<HorizonPolyline> sweep_sections(const SampleGrid& grid, const SurfaceDrawing& d,
                                            const SurfaceScreen& screen) {
  detail::HorizonSweep sweep(screen.width, screen.columns);
  // Sweep coordinates: screen x, and height above the origin growing upwards.
  const auto at = [&](std::size_t j, std::size_t i) {
    const ScreenPoint& p = grid.points[j * grid.nx + i];
    return ScreenPoint{d.origin_x + d.scale_x * p.x, d.scale_y * p.y};
  };
  const auto add_if_finite = [&](ScreenPoint a, ScreenPoint b) {
    if (std::isnan(a.x) || std::isnan(b.x)) return sweep.break_polyline();
    sweep.add_segment(a, b);
  };
  const std::size_t last = grid.nx - 1;
  for (std::size_t j = 0; j < grid.nz; ++j) {
    sweep.begin_section(j == 0 ? HorizonSide::first : HorizonSide::upper);
    const bool edges = screen.side_edges && j > 0;
    if (edges) add_if_finite(at(j - 1, 0), at(j, 0));
    for (std::size_t i = 0; i < last; ++i) add_if_finite(at(j, i), at(j, i + 1));
    if (edges) add_if_finite(at(j, last), at(j - 1, last));
    sweep.end_section();
  }
  return sweep.take_polylines();
}

}  // namespace

Status check_surface_request(const SurfaceView& view, const SurfaceScreen& screen) {
  if (Status status = check_view(view); !status) return status;
  if (!(screen.width > 0.0 && screen.height > 0.0 && std::isfinite(screen.width) &&
        std::isfinite(screen.height))) {
    return Status::failure(
        Code::usage_error,
        fmt::format("screen size must be positive, got {} x {}", screen.width, screen.height));
  }
  if (!(screen.margin >= 0.0 && 2.0 * screen.margin < std::min(screen.width, screen.height))) {
    return Status::failure(Code::usage_error,
                           fmt::format("margin {} leaves no room on a {} x {} screen",
                                       screen.margin, screen.width, screen.height));
  }
  if (screen.columns < 1 || screen.columns > kMaxColumns) {
    return Status::failure(Code::usage_error, fmt::format("columns must lie in [1, {}], got {}",
                                                          kMaxColumns, screen.columns));
  }
  return Status::success();
}

SurfaceDrawing draw_floating_horizon(const SurfaceFunction& f, const SurfaceView& view,
                                     const SurfaceScreen& screen) {
  throw_if_failed(check_surface_request(view, screen), "draw_floating_horizon");
  SurfaceDrawing drawing;
  drawing.width = screen.width;
  drawing.height = screen.height;
  const SampleGrid grid = sample_surface(f, view);
  if (!fit_window(grid, screen, drawing)) return drawing;
  drawing.polylines = sweep_sections(grid, drawing, screen);
  for (HorizonPolyline& line : drawing.polylines) {
    for (ScreenPoint& p : line.points) p.y = drawing.origin_y - p.y;
  }
  return drawing;
}

}  // namespace roomcad
