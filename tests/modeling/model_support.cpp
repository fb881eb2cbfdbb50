#include "model_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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

BuildOptions options_for(BooleanPath path, int threads) {
  BuildOptions options;
  options.boolean = path;
  options.threads = threads;
  return options;
}

std::map<FaceKind, double> area_by_kind(const SolidMesh& mesh) {
  std::map<FaceKind, double> area;
  const FacePropertyHandles props = face_property_handles(mesh);
  for (const auto f : mesh.faces()) {
    std::vector<OpenMesh::Vec3d> p;
    for (const auto v : mesh.fv_range(f)) p.push_back(mesh.point(v));
    OpenMesh::Vec3d n(0, 0, 0);
    for (std::size_t i = 1; i + 1 < p.size(); ++i) n += OpenMesh::cross(p[i] - p[0], p[i + 1] - p[0]);
    area[mesh.property(props.kind, f)] += n.norm() / 2.0;
  }
  return area;
}

SolidCheck expect_valid_walls(const Plan& plan, BooleanPath path, long genus, double expected_volume) {
  const Model model = build_model(plan, options_for(path));
  const SolidCheck c = check_solid(model.walls);
  const char* name = path == BooleanPath::cgal ? "cgal" : "auto";
  EXPECT_TRUE(c.is_closed()) << name << ": " << c.border_edges << " border edges";
  EXPECT_TRUE(c.is_manifold()) << name << ": " << c.non_manifold_vertices << " non-manifold vertices, "
                               << c.rejected_triangles << " rejected triangles";
  EXPECT_EQ(c.self_intersections, 0u) << name;
  EXPECT_EQ(c.degenerate_triangles, 0u) << name;
  EXPECT_EQ(c.inward_components, 0u) << name;
  EXPECT_EQ(c.genus, genus) << name;
  const double analytic = analytic_wall_volume(plan);
  EXPECT_NEAR(c.volume, analytic, 1e-9 * analytic) << name;
  if (expected_volume > 0.0) {
    EXPECT_NEAR(analytic, expected_volume, 1e-9 * expected_volume) << name;
  }
  return c;
}

void expect_paths_agree(const Plan& plan, long genus, double expected_volume) {
  const SolidCheck fast = expect_valid_walls(plan, BooleanPath::automatic, genus, expected_volume);
  const SolidCheck cgal = expect_valid_walls(plan, BooleanPath::cgal, genus, expected_volume);
  EXPECT_NEAR(fast.volume, cgal.volume, 1e-9 * cgal.volume);
  const auto a = area_by_kind(build_model(plan, options_for(BooleanPath::automatic)).walls);
  const auto b = area_by_kind(build_model(plan, options_for(BooleanPath::cgal)).walls);
  for (const auto& [kind, area] : b) EXPECT_TRUE(a.count(kind)) << "only cgal has " << to_string(kind);
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [kind, area] : a) {
    ASSERT_TRUE(b.count(kind)) << to_string(kind);
    EXPECT_NEAR(area, b.at(kind), 1e-9 * area) << to_string(kind);
  }
}

}  // namespace roomcad::test
