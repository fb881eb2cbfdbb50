// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/wall_check_format.h"

#include <cmath>

#include <fmt/format.h>

namespace roomcad {

namespace {

std::string yes_no(bool b) { return b ? "yes" : "NO"; }

}  // namespace

std::string format_wall_check_text(const WallCheck& v) {
  const SolidCheck& c = v.solid;
  std::string out =
      fmt::format("wall solid: {} vertices, {} faces ({} triangles), {} component{}\n", c.vertices,
                  c.faces, c.triangles, c.components, c.components == 1 ? "" : "s");
  out += fmt::format("  closed              {} ({} border edges)\n", yes_no(c.is_closed()),
                     c.border_edges);
  out += fmt::format("  2-manifold          {} ({} non-manifold vertices, {} rejected triangles)\n",
                     yes_no(c.is_manifold()), c.non_manifold_vertices, c.rejected_triangles);
  out +=
      fmt::format("  self-intersections  {}{}\n", c.self_intersections,
                  c.touching_pairs == 0
                      ? ""
                      : fmt::format(" ({} pairs of triangles touch at a shared point or edge only)",
                                    c.touching_pairs));
  out += fmt::format("  degenerate faces    {}\n", c.degenerate_triangles);
  out += fmt::format("  outward oriented    {} ({} inward components{})\n",
                     yes_no(c.inward_components == 0), c.inward_components,
                     c.cavities == 0 ? "" : fmt::format(", {} cavities", c.cavities));
  out += fmt::format("  genus               {}\n", c.genus);
  out += fmt::format("  volume              {} m^3\n", c.volume);
  out += fmt::format(
      "  analytic volume     {} m^3 (relative difference {:.3g}, limit 1e-09 plus {:.2g} m^3 "
      "of rounding)\n",
      v.analytic, v.relative, v.limit - kWallVolumeTolerance * std::abs(v.analytic));
  out += fmt::format("check: {}\n", v.ok ? "ok" : "FAILED");
  return out;
}

std::string format_wall_check_json(const WallCheck& v) {
  const SolidCheck& c = v.solid;
  return fmt::format(
      "{{\"ok\": {}, \"vertices\": {}, \"faces\": {}, \"triangles\": {}, \"components\": {}, "
      "\"closed\": {}, \"border_edges\": {}, \"manifold\": {}, \"non_manifold_vertices\": {}, "
      "\"rejected_triangles\": {}, \"self_intersections\": {}, \"touching_pairs\": {}, "
      "\"degenerate_faces\": {}, "
      "\"outward\": {}, \"cavities\": {}, \"genus\": {}, \"volume\": {}, \"analytic_volume\": {}, "
      "\"relative_difference\": {}, \"volume_limit\": {}}}\n",
      v.ok, c.vertices, c.faces, c.triangles, c.components, c.is_closed(), c.border_edges,
      c.is_manifold(), c.non_manifold_vertices, c.rejected_triangles, c.self_intersections,
      c.touching_pairs, c.degenerate_triangles, c.inward_components == 0, c.cavities, c.genus,
      c.volume, v.analytic, v.relative, v.limit);
}

}  // namespace roomcad
