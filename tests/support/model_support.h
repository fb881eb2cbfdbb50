// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers for the modeling tests: small plans, and the checks every built solid must pass.
#pragma once

#include <map>
#include <string>

#include "mesh/mesh_check.h"
#include "plan/plan.h"
#include "solid/build_model.h"
#include "solid/wall_check.h"
#include "support/solid_tolerance.h"

namespace roomcad::test {

constexpr auto kDoor = OpeningType::door;
constexpr auto kWindow = OpeningType::window;

/// A plan on a large site with no walls.
Plan empty_plan();
/// Appends a wall (thickness 0.2, height 2.5, base 0).
Wall& add_wall(Plan& plan, const std::string& id, Point2 from, Point2 to);
/// Appends an opening to `wall` spanning [offset, offset + width] x [sill, sill + height].
Opening& add_opening(Plan& plan, const std::string& id, OpeningType type, const std::string& wall,
                     double offset, double width, double sill, double height);
/// A closed rectangular room of four mitred walls, counter-clockwise from (x, y).
void add_room(Plan& plan, const std::string& prefix, double x, double y, double w, double h);
/// Rotates every wall of the plan by `degrees` about the origin, then moves it by (dx, dy).
Plan transformed(const Plan& plan, double degrees, double dx, double dy);

/// Expects build_model(plan, options) to throw a PreconditionError with this code whose message
/// holds `names` (the objects and reason it must name).
void expect_build_refused(const Plan& plan, const BuildOptions& options, Code code,
                          const std::string& names);

/// Build options for one path and thread count.
BuildOptions options_for(BooleanPath path, int threads = 0);

/// Builds the walls on one path and checks them: closed, 2-manifold, no self-intersection,
/// no degenerate face, outward; volume equal to the analytic volume within volume_tolerance
/// (1e-9 relative away from huge coordinates) and to `expected_volume` (if positive) within
/// 1e-9 relative; genus as given. @return the check.
SolidCheck expect_valid_walls(const Plan& plan, BooleanPath path, long genus,
                              double expected_volume = 0.0);

/// Builds on the automatic, general (with and without BuildOptions::grid_planes) and Nef paths,
/// checks each, and expects the same volume and area of each face kind as Nef's (within 1e-9
/// relative plus what vertex_rounding allows).
void expect_paths_agree(const Plan& plan, long genus, double expected_volume = 0.0);

}  // namespace roomcad::test
