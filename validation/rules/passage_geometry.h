// SPDX-License-Identifier: GPL-3.0-or-later
// The geometry of passage_too_narrow (passages.cpp): the wall pieces of a storey, the
// barriers between pieces closer than the passage width, positions along a room's outline,
// and the fixes that widen a barrier. Plain header.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "validation/report.h"
#include "validation/rules/context.h"
#include "validation/rules/convex.h"
#include "validation/rules/scene.h"

namespace roomcad::rules {

/// A piece of a wall's footprint between its door holes (wall_pieces' `index`-th).
struct Piece {
  std::size_t wall = 0;
  std::size_t index = 0;
  std::vector<Point2> corners;  ///< doubles, counter-clockwise
};

/// Two pieces of different walls closer than the passage width, inside a room.
struct Barrier {
  std::size_t p = 0;  ///< piece indices
  std::size_t q = 0;
  Point2 a;  ///< closest points on p and q (doubles)
  Point2 b;
  double gap = 0.0;  ///< |a - b|, about
  std::size_t room = 0;
};

struct PassageFix {
  std::string text;
  std::vector<FixEdit> edits;
};

/// A room's outline as a closed path: positions along it by arc length.
class Outline {
 public:
  explicit Outline(const std::vector<Point2>& points);
  /// @return the arc length to the point of the outline nearest p.
  [[nodiscard]] double param(Point2 p) const;

 private:
  std::vector<Point2> points_;
  std::vector<double> start_;  ///< arc length at each corner
};

/// @return the middle of a door's hole on its wall's face: side 0 right, 1 left.
[[nodiscard]] Point2 door_face_middle(const Wall& w, const Opening& o, int side);

class PassageGeometry {
 public:
  /// Finds the barriers of a storey narrower than `width`. O(n log n + k) for n pieces and k
  /// pairs of pieces whose boxes come within `width`; exact tests only near the width or 0.
  PassageGeometry(const Scene& scene, const Storey& storey, double width);

  [[nodiscard]] std::size_t barrier_count() const { return barriers_.size(); }
  [[nodiscard]] const Barrier& barrier(std::size_t i) const { return barriers_[i]; }
  [[nodiscard]] const Piece& piece(std::size_t i) const { return pieces_[i]; }

  /// A fix that makes the barrier's two walls at least `width` apart: shorten a free end of
  /// either, or move one of them away from the other; tried on the neighbourhood, where the
  /// room must still be found and the two walls' pieces must no longer be closer than `width`.
  [[nodiscard]] std::optional<PassageFix> find_fix(const Barrier& barrier, double width) const;

 private:
  void add_barrier(std::size_t p, std::size_t q, double width, const RoomLocator& locator);

  const Scene& scene_;
  const Storey& storey_;
  std::vector<Piece> pieces_;
  std::vector<Barrier> barriers_;
};

}  // namespace roomcad::rules
