// SPDX-License-Identifier: GPL-3.0-or-later
// A plan prepared for the rules' geometric tests: its joins, which walls and openings can be
// tested, the walls' boxes and an index of them. Built for the plan being validated, and for
// small neighbourhoods of it when a fix is tried (fix_search.h). Plain header.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "core/flat_index.h"
#include "geometry/box_grid.h"
#include "geometry/broad_phase.h"
#include "geometry/joins.h"
#include "plan/plan.h"

namespace roomcad::rules {

struct Span;

class Scene {
 public:
  /// @param[in] usable  by wall: passed validation's value checks
  /// @param[in] host    by opening: its usable host wall
  Scene(const Plan& plan, const Joins& joins, std::vector<bool> usable,
        std::vector<std::optional<std::size_t>> host);
  /// A plan on its own (a neighbourhood with a fix applied): joins found here, walls usable
  /// when their numbers are finite with positive length and thickness, hosts by id.
  explicit Scene(const Plan& plan);

  [[nodiscard]] const Plan& plan() const { return plan_; }
  [[nodiscard]] const Joins& joins() const { return *joins_; }
  [[nodiscard]] bool is_usable(std::size_t wall) const { return usable_[wall]; }
  [[nodiscard]] const std::optional<std::size_t>& host(std::size_t opening) const {
    return host_[opening];
  }
  /// @return an outward-rounded box of the wall's footprint (usable walls only).
  [[nodiscard]] const Box2& wall_box(std::size_t wall) const { return boxes_[wall]; }
  /// @return the usable walls whose boxes meet `box`, sorted.
  [[nodiscard]] std::vector<std::size_t> walls_near(const Box2& box) const {
    return grid_.find(box);
  }
  /// @return the boxes of the usable walls (index = wall), for batch broad phases.
  [[nodiscard]] const std::vector<Box2>& usable_boxes() const { return usable_boxes_; }
  /// @return the index of the wall with this id (the first, if ids repeat), or nullopt. O(1).
  [[nodiscard]] std::optional<std::size_t> wall_named(std::string_view id) const;
  /// @return the openings that name wall `wall` as theirs (usable or not), in plan order.
  [[nodiscard]] const std::vector<std::size_t>& openings_of(std::size_t wall) const {
    return openings_of_[wall];
  }
  /// @return the door holes of a wall, sorted along it.
  [[nodiscard]] std::vector<Span> door_holes(std::size_t wall) const;

 private:
  void index_walls();
  void index_doors();

  const Plan& plan_;
  std::unique_ptr<Joins> owned_joins_;
  const Joins* joins_;
  std::vector<bool> usable_;
  std::vector<std::optional<std::size_t>> host_;
  IdIndex wall_ids_;
  std::vector<std::vector<std::size_t>> openings_of_;  ///< by wall: openings naming it
  std::vector<std::vector<std::size_t>>
      doors_of_;  ///< by wall: hosted doors  ///< by wall: hosted doors
  std::vector<Box2> boxes_;
  std::vector<Box2> usable_boxes_;
  BoxGrid grid_;
};

/// @return the box grown by `margin` metres on every side.
[[nodiscard]] Box2 grown(Box2 box, double margin);

}  // namespace roomcad::rules
