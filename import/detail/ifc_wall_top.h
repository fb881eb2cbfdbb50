// SPDX-License-Identifier: GPL-3.0-or-later
// The top and bottom of an IFC wall after the half-spaces its clippings remove (roof planes
// over a wall, a floor under it), read along its centre line as the plan's walls hold them:
// one sloped top where one plane cuts the whole top, else walls split where the planes over it
// meet or their boundaries end (two for a gable), each with its plane's sloped top.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "import/detail/ifc_geometry.h"
#include "plan/plan.h"

namespace roomcad::ifc {

/// A stretch of the centre line, metres from its start, with the world z of its top at each end.
struct TopPiece {
  double from = 0.0;
  double to = 0.0;
  double top_from = 0.0;
  double top_to = 0.0;
};

struct WallTop {
  double bottom = 0.0;               ///< world z, metres
  std::vector<TopPiece> pieces{};    ///< in order along the centre line, covering it
  double error = 0.0;                ///< metres between these tops and the clipped body's
  std::vector<std::string> notes{};  ///< what is approximated, for a warning
};

/// Reads the top of a straight wall from `from` to `to` (world metres), `thickness` thick, its
/// unclipped body from world z `bottom` to `top`, less `clips` (file units, `k` metres each).
/// The pieces are exact over the centre line but for stretches shorter than 1 cm, merged into
/// their neighbours, and a top sloping across the thickness (read at the centre line); `error`
/// is measured at 65 points along it. O(clips^2 + 65 clips).
[[nodiscard]] WallTop clipped_top(Point2 from, Point2 to, double thickness, double bottom,
                                  double top, const std::vector<Clip>& clips, double k);

/// A wall written as its elevation: a profile in a vertical plane swept horizontally across it
/// (BricsCAD's arched and gable walls), in metres.
struct UprightWall {
  Point2 from{};  ///< centre line ends, at the middle of the sweep
  Point2 to{};
  double thickness = 0.0;  ///< the sweep's length
  WallTop top{};           ///< over the flat bottom, its chords merged within kUprightTolerance
};

/// Metres a merged stretch of an upright wall's top may lie from the profile's.
inline constexpr double kUprightTolerance = 0.01;

/// @return the upright wall of prism `p` (file units, `k` metres each), or nothing with `why`
///   when the sweep is not horizontal and across the profile, or the profile does not stand on
///   a flat bottom with one top over each point (an arch over a doorway does not). O(n^2) in
///   the profile's corners.
[[nodiscard]] std::optional<UprightWall> upright_wall(const Prism& p, double k, std::string& why);

}  // namespace roomcad::ifc
