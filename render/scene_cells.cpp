// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/scene_cells.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/box_grid.h"

namespace roomcad {
namespace {

Box3 grown(Box3 b, double margin) {
  for (std::size_t k = 0; k < 3; ++k) b.low[k] -= margin, b.high[k] += margin;
  return b;
}

double plan_diagonal(const Box3& b) {
  return std::hypot(b.high[0] - b.low[0], b.high[1] - b.low[1]);
}

/// A box a cell's triangles meet: its own prism (portal < 0) or one of its portals' holes.
struct Region {
  Box3 box;
  std::uint32_t cell = 0;
  std::int64_t portal = -1;
};

/// Appends triangle i (of cluster `cluster`) to a cell's runs: the last run grows when it ends
/// at i within the same cluster.
void add_to_runs(std::vector<Cluster>& runs, std::uint32_t i, const Cluster& cluster,
                 const Box3& box) {
  if (!runs.empty() && runs.back().first + runs.back().count == i &&
      runs.back().first >= cluster.first) {
    Cluster& run = runs.back();
    ++run.count;
    add_point(run.bounds, box.low[0], box.low[1], box.low[2]);
    add_point(run.bounds, box.high[0], box.high[1], box.high[2]);
    return;
  }
  runs.push_back({.first = i, .count = 1, .bounds = box, .passes = cluster.passes});
}

}  // namespace

double cell_reach(double diagonal) {
  return std::max(0.01, diagonal * kPortalPlaneTolerance / kPortalEyeClearance);
}

SceneCells index_cells(const Cells& cells, const Scene& scene) {
  SceneCells out{.cells = cells,
                 .runs = std::vector<std::vector<Cluster>>(cells.cells.size()),
                 .indexed_triangles = scene.triangle_count()};
  std::vector<Region> regions;
  std::vector<double> reach(cells.cells.size());
  for (std::size_t c = 0; c < cells.cells.size(); ++c) {
    reach[c] = cell_reach(plan_diagonal(cells.cells[c].bounds));
    regions.push_back({grown(cells.cells[c].bounds, reach[c]), static_cast<std::uint32_t>(c)});
  }
  for (std::size_t p = 0; p < cells.portals.size(); ++p) {
    double r = 0.0;
    for (std::uint32_t c : cells.portals[p].cells) r = std::max(r, reach[c]);
    regions.push_back({grown(cells.portals[p].bounds, r), 0, static_cast<std::int64_t>(p)});
  }
  std::vector<Box2> boxes;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const Box3& b = regions[k].box;
    boxes.push_back({b.low[0], b.low[1], b.high[0], b.high[1], k});
  }
  BoxGrid grid(std::move(boxes));
  std::vector<std::uint32_t> last(cells.cells.size(), std::numeric_limits<std::uint32_t>::max());
  const glm::dvec3 o = scene.origin;
  for (const Cluster& cluster : scene.clusters) {
    for (std::uint32_t i = cluster.first; i < cluster.first + cluster.count; ++i) {
      Box3 local = empty_box3();  // in the scene's frame
      for (int k = 0; k < 3; ++k) {
        const glm::vec3& c = scene.corners[3 * std::size_t(i) + k];
        add_point(local, c.x, c.y, c.z);
      }
      const Box3 world{{local.low[0] + o.x, local.low[1] + o.y, local.low[2] + o.z},
                       {local.high[0] + o.x, local.high[1] + o.y, local.high[2] + o.z}};
      auto add = [&](std::uint32_t c) {
        if (last[c] == i) return;
        last[c] = i;
        add_to_runs(out.runs[c], i, cluster, local);
      };
      grid.for_each_meeting({world.low[0], world.low[1], world.high[0], world.high[1], 0},
                            [&](std::size_t k) {
                              const Region& r = regions[k];
                              if (!boxes_meet(r.box, world)) return;
                              if (r.portal < 0) return add(r.cell);
                              for (std::uint32_t c : cells.portals[std::size_t(r.portal)].cells)
                                add(c);
                            });
    }
  }
  return out;
}

}  // namespace roomcad
