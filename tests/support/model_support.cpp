// SPDX-License-Identifier: GPL-3.0-or-later
#include "support/model_support.h"
#include "solid/analytic_volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace roomcad::test {

Plan empty_plan() {
  Plan plan;
  plan.site.origin = {-50.0, -50.0};
  plan.site.cells = {100, 100};
  return plan;
}

Wall& add_wall(Plan& plan, const std::string& id, Point2 from, Point2 to) {
  Wall& w = plan.walls.emplace_back();
  w.id = id, w.from = from, w.to = to, w.thickness = 0.2, w.height = 2.5;
  return w;
}

Opening& add_opening(Plan& plan, const std::string& id, OpeningType type, const std::string& wall,
                     double offset, double width, double sill, double height) {
  Opening& o = plan.openings.emplace_back();
  o.id = id, o.type = type, o.wall = wall, o.offset = offset;
  o.width = width, o.height = height, o.sill = sill;
  return o;
}

void add_room(Plan& plan, const std::string& prefix, double x, double y, double w, double h) {
  const Point2 c[4] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
  for (int k = 0; k < 4; ++k) add_wall(plan, prefix + std::to_string(k), c[k], c[(k + 1) % 4]);
}

Plan transformed(const Plan& plan, double degrees, double dx, double dy) {
  Plan out = plan;
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  auto move = [&](Point2 p) { return Point2{c * p.x - s * p.y + dx, s * p.x + c * p.y + dy}; };
  for (Wall& w : out.walls) w.from = move(w.from), w.to = move(w.to);
  out.site.origin = {dx - 100.0, dy - 100.0};
  out.site.cells = {2, 2};
  out.site.cell_size = 100.0;
  return out;
}

void expect_build_refused(const Plan& plan, const BuildOptions& options, Code code,
                          const std::string& names) {
  try {
    (void)build_model(plan, options);
    ADD_FAILURE() << "built; expected a refusal naming " << names;
  } catch (const PreconditionError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(names), std::string::npos) << e.what();
  }
}

BuildOptions options_for(BooleanPath path, int threads) {
  BuildOptions options;
  options.boolean = path;
  options.threads = threads;
  return options;
}

namespace {

/// The area error the mesh's doubles allow: 1e-9 relative, plus the length of all face
/// boundaries times vertex_rounding (a face's area moves by at most its perimeter x d).
double area_tolerance(const SolidMesh& mesh, double area) {
  double boundary = 0.0;
  for (const auto e : mesh.edges()) boundary += 2.0 * mesh.calc_edge_length(e);
  return 1e-9 * area + boundary * vertex_rounding(mesh);
}

/// The checks of expect_valid_walls on walls already built.
SolidCheck expect_valid_model(const Model& model, const Plan& plan, BooleanPath path, long genus,
                              double expected_volume) {
  const SolidCheck c = check_solid(model.walls);
  const char* name = path == BooleanPath::nef       ? "nef"
                     : path == BooleanPath::general ? "general"
                                                    : "auto";
  EXPECT_TRUE(c.is_closed()) << name << ": " << c.border_edges << " border edges";
  EXPECT_TRUE(c.is_manifold()) << name << ": " << c.non_manifold_vertices
                               << " non-manifold vertices, " << c.rejected_triangles
                               << " rejected triangles";
  EXPECT_EQ(c.self_intersections, 0u) << name;
  EXPECT_EQ(c.degenerate_triangles, 0u) << name;
  EXPECT_EQ(c.inward_components, 0u) << name;
  EXPECT_EQ(c.genus, genus) << name;
  const double analytic = analytic_wall_volume(plan);
  EXPECT_NEAR(c.volume, analytic, volume_tolerance(model.walls, analytic)) << name;
  if (expected_volume > 0.0) {
    EXPECT_NEAR(analytic, expected_volume, 1e-9 * expected_volume) << name;
  }
  return c;
}

}  // namespace

SolidCheck expect_valid_walls(const Plan& plan, BooleanPath path, long genus,
                              double expected_volume) {
  return expect_valid_model(build_model(plan, options_for(path)), plan, path, genus,
                            expected_volume);
}

void expect_paths_agree(const Plan& plan, long genus, double expected_volume) {
  const Model nef_model = build_model(plan, options_for(BooleanPath::nef));
  const SolidCheck nef =
      expect_valid_model(nef_model, plan, BooleanPath::nef, genus, expected_volume);
  const auto b = area_by_kind(nef_model.walls);
  // The general path also without its grid of planes of rectangles (every plane through the
  // general 2D boolean).
  for (const auto& [path, grid] :
       {std::pair{BooleanPath::automatic, true}, std::pair{BooleanPath::general, true},
        std::pair{BooleanPath::general, false}}) {
    SCOPED_TRACE(path == BooleanPath::general ? grid ? "general path" : "general path, no grid"
                                              : "automatic path");
    BuildOptions options = options_for(path);
    options.grid_planes = grid;
    const Model model = build_model(plan, options);
    const SolidCheck c = expect_valid_model(model, plan, path, genus, expected_volume);
    EXPECT_NEAR(c.volume, nef.volume, 2 * volume_tolerance(nef_model.walls, nef.volume));
    const auto a = area_by_kind(model.walls);
    for (const auto& [kind, area] : b)
      EXPECT_TRUE(a.count(kind)) << "only nef has " << to_string(kind);
    for (const auto& [kind, area] : a)
      EXPECT_TRUE(b.count(kind)) << "only this path has " << to_string(kind) << " " << area;
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [kind, area] : a) {
      ASSERT_TRUE(b.count(kind)) << to_string(kind);
      EXPECT_NEAR(area, b.at(kind), 2 * area_tolerance(nef_model.walls, area)) << to_string(kind);
    }
  }
}

}  // namespace roomcad::test
