// SPDX-License-Identifier: GPL-3.0-or-later
// Is there a free circle of radius rho in a room? The question no_turning_circle asks, and its
// fix asks again on the edited neighbourhood.
//
// The circle fits where its centre is at least rho from every wall footprint of the storey
// (doors closed) and inside the room. The set of such centres, when not empty, has a corner
// where two of the lines at rho from wall faces and ends cross, or one such line or two
// circles of radius rho about wall corners meet. Candidates are made there in doubles, ranked
// by their clearance, and verified exactly (the distance to each footprint compared squared,
// in the written numbers); where a candidate lies within 1e-9 m of touching, the crossing of
// two lines is rebuilt exactly and verified. A circle that fits with no room to spare while
// touching a wall corner (not a face) is the one case that may be missed. Plain header.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "plan/plan.h"
#include "validation/rules/context.h"
#include "validation/rules/scene.h"

namespace roomcad::rules {

/// The walls of one storey as obstacles to people, with their footprints in doubles.
class StoreyWalls {
 public:
  StoreyWalls(const Scene& scene, const std::vector<std::size_t>& walls);
  /// @return the storey's walls whose boxes meet `box`.
  [[nodiscard]] std::vector<std::size_t> near(const Box2& box) const;
  /// @return the distance in doubles from p to the nearest of `walls` (not exact).
  [[nodiscard]] double clearance(Point2 p, const std::vector<std::size_t>& walls) const;
  [[nodiscard]] const std::array<Point2, 4>& quad(std::size_t wall) const { return quads_[wall]; }
  [[nodiscard]] const Scene& scene() const { return scene_; }

 private:
  const Scene& scene_;
  std::vector<bool> member_;
  std::vector<std::array<Point2, 4>> quads_;
};

struct FreeDisc {
  bool fits = false;
  Point2 centre;         ///< where it fits (or the best place found)
  double clearance = 0;  ///< that place's distance to the walls (doubles), about
};

/// @param[in] rooms, room  the storey's rooms and the one to search
/// @param[in] locator      RoomLocator(rooms)
/// @param[in] diameter     of the circle, metres (a written number: 1.5 is exactly 3/2)
/// @return whether the circle fits in the room; exact as the file comment says.
[[nodiscard]] FreeDisc find_free_disc(const StoreyWalls& walls, const std::vector<Room>& rooms,
                                      const RoomLocator& locator, std::size_t room,
                                      double diameter);

/// @return the diameter of the largest free circle of the room, less than `diameter`, to
///         about 1 mm (doubles, by bisection on find_free_disc's candidates; for messages
///         and fixes, never for verdicts).
[[nodiscard]] double largest_free_diameter(const StoreyWalls& walls, const std::vector<Room>& rooms,
                                           const RoomLocator& locator, std::size_t room,
                                           double diameter);

}  // namespace roomcad::rules
