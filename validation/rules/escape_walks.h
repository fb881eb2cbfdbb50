// SPDX-License-Identifier: GPL-3.0-or-later
// Walking distances to the exterior doors, for escape_too_far. They are geodesic lengths in
// the free space, which roomcad computes approximately, with both bounds:
//  - upper: real walks, made of straight lines (inside one room, or through one door) between
//    points 1 cm off the walls: the middle and both ends of each door's hole (10 cm in from
//    each jamb) on either face, and the room's inner corners. Every such walk can be walked,
//    so the distance is at most this;
//  - lower: a walk passes the holes of its doors in turn, and from one hole to the next it is
//    at least as long as the straight distance between the two hole segments; so the distance
//    is at least the shortest chain of such segment distances.
// The longest walk of a room is bounded over sample points (its corners, the middles of its
// sides and a grid) plus the sampling spacing, since distances change by at most the distance
// moved; the spacing is refined when the bounds straddle the limit. Plain header.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "plan/plan.h"
#include "validation/rules/context.h"
#include "validation/rules/scene.h"

namespace roomcad::rules {

/// The longest walk from a point of a room to an exterior door, bounded.
struct WalkBounds {
  double lower = 0.0;
  double upper = 0.0;
  Point2 farthest;  ///< the sample with the longest walk
};

class EscapeWalks {
 public:
  /// Shortest walks from every door point of the storey to the exterior doors. O(sum over
  /// rooms of (points in the room)^2 + n log n).
  EscapeWalks(const Scene& scene, const Storey& storey);

  /// @return the room's bounds, sampled `spacing` apart, or nullopt if no exterior door can
  ///         be reached from it. O(samples * points of the room).
  [[nodiscard]] std::optional<WalkBounds> longest_walk(std::size_t room, double spacing) const;

  /// @return the upper bound of the room's longest walk if the walk ended at `exits` (points
  ///         in the room) plus `beyond` metres, and no other door led out.
  [[nodiscard]] double walk_to(std::size_t room, const std::vector<Point2>& exits, double beyond,
                               double spacing) const;

  /// @return the points of a door's hole on one face, 1 cm off it: at 10 cm (or a quarter of
  ///         the width) in from each jamb, and the middle. side +1: the wall's left face.
  [[nodiscard]] static std::vector<Point2> door_points(const Wall& w, double lo, double hi,
                                                       int side);

 private:
  struct Point {
    Point2 p;
    std::optional<std::size_t> room;  ///< nullopt: outside
  };
  void add_door_points(std::size_t door, std::size_t wall);
  void link_rooms();
  void find_upper_walks();
  void find_lower_walks();
  [[nodiscard]] std::vector<Point2> samples(std::size_t room, double spacing) const;
  [[nodiscard]] bool is_visible(std::size_t room, Point2 a, Point2 b) const;

  const Scene& scene_;
  const Storey& storey_;
  std::vector<Point> points_;
  std::vector<std::vector<std::pair<std::size_t, double>>> links_;
  std::vector<std::vector<std::size_t>>
      room_points_;            ///< by room: its door points and inner corners
  std::vector<bool> convex_;   ///< by room
  std::vector<double> upper_;  ///< by point: walk to outside
  std::vector<double> lower_;  ///< by door (storey order): bound from its hole
  std::vector<std::vector<std::size_t>> room_doors_;  ///< by room: its doors (storey order)
};

}  // namespace roomcad::rules
