// SPDX-License-Identifier: GPL-3.0-or-later
// The floating-horizon drawing of a surface y = f(x, z) (lab 4, variant 3 of the Tomsk manual
// "Laboratory works in computer graphics"): the surface is cut by the planes z = const, taken from
// the front (z_min) to the back; each section is drawn where it lies above the upper or below the
// lower horizon of the sections before it, with its crossings of the horizons found by linear
// intersection.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"

namespace roomcad {

/// What part of the surface a range of sample points, and the rotation that shows it.
struct SurfaceView {
  double x_min = -1.0, x_max = 1.0;  ///< x range, x_min < x_max
  double z_min = -1.0, z_max = 1.0;  ///< z range (the sections), z_min <= z_max
  double dx = 0.1;                   ///< step along each section, > 0 (shrunk to divide evenly)
  double dz = 0.1;                   ///< step between sections, > 0 (shrunk likewise)
  double rotate_x_deg = 0.0;  ///< second rotation, about x, in (-90, 90); > 0 looks from above
  double rotate_y_deg = 0.0;  ///< first rotation, about y, in (-90, 90)
};

/// The screen (or paper) the drawing fills, in any unit; y grows downwards.
struct SurfaceScreen {
  double width = 800.0;
  double height = 600.0;
  double margin = 10.0;  ///< blank border kept on every side
  int columns = 800;     ///< resolution of the horizon arrays (one per pixel in the classic method)
  bool side_edges = true;  ///< also draw the x = x_min and x = x_max edges between sections
  /// true: one scale for both axes (terrain); false: stretch each axis to fill the screen, as
  /// the seed's window does
  bool keep_aspect = false;
};

/// Why a piece of a section is visible: it is on the first (front) section, above the upper
/// horizon (the top of the surface) or below the lower horizon (its underside).
enum class HorizonSide : std::uint8_t { first, upper, lower };

struct ScreenPoint {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const ScreenPoint&, const ScreenPoint&) = default;
};

/// A visible polyline: sample points of a section plus the points where it meets a horizon.
struct HorizonPolyline {
  HorizonSide side = HorizonSide::first;
  std::vector<ScreenPoint> points;  ///< at least two
};

/// The result, with the picture-plane-to-screen map so callers can relate it to the surface:
/// screen x = origin_x + scale_x * X, screen y = origin_y - scale_y * Y, where (X, Y) is the
/// rotated point (X = x cos ry + z sin ry, Y = y cos rx + (z cos ry - x sin ry) sin rx).
struct SurfaceDrawing {
  double width = 0.0;
  double height = 0.0;
  double scale_x = 1.0;
  double scale_y = 1.0;
  double origin_x = 0.0;
  double origin_y = 0.0;
  std::vector<HorizonPolyline> polylines;  ///< in drawing order (front to back)
};

/// The function drawn; NaN (or any non-finite value) marks a missing sample, drawn as a gap.
using SurfaceFunction = std::function<double(double x, double z)>;

/// Checks a view and a screen. @return success, or a usage_error naming the field and its
/// value (e.g. "dx must be positive, got -1").
[[nodiscard]] Status check_surface_request(const SurfaceView& view, const SurfaceScreen& screen);

/// Draws y = f(x, z) by the floating-horizon method. The picture is scaled to fill the screen
/// inside its margin (see SurfaceScreen::keep_aspect) and centred. Missing samples cut the sections
/// they lie on.
/// @param[in] f       called once per sample, from several threads at once (must be pure)
/// @pre check_surface_request(view, screen).ok()
/// @return the visible polylines; none if f has no finite sample. Deterministic.
///   Cost: O(nx * nz) evaluations plus O(nz * (nx + columns)) for the horizons.
/// @throws PreconditionError (usage_error) if the precondition fails.
[[nodiscard]] SurfaceDrawing draw_floating_horizon(const SurfaceFunction& f,
                                                   const SurfaceView& view,
                                                   const SurfaceScreen& screen);

}  // namespace roomcad
