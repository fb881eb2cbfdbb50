// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <vector>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_set_2.h>

#include "modeling/detail/buildable_plan.h"
#include "modeling/detail/exact_wall.h"
#include "modeling/mesh_check.h"

namespace roomcad {
namespace {

using detail::EK;
using Polygon = CGAL::Polygon_2<EK>;
using PolygonSet = CGAL::Polygon_set_2<EK>;

struct Prism {
  Polygon outline;
  double z0, z1;
};

Polygon to_polygon(const std::vector<EK::Point_2>& q) { return Polygon(q.begin(), q.end()); }

// The union of the prisms' outlines over the slab [z0, z1].
PolygonSet union_in_slab(const std::vector<Prism>& prisms, double z0, double z1) {
  std::vector<Polygon> present;
  for (const Prism& p : prisms)
    if (p.z0 <= z0 && p.z1 >= z1 && !p.outline.is_empty()) present.push_back(p.outline);
  PolygonSet set;
  if (!present.empty()) set.join(present.begin(), present.end());
  return set;
}

EK::FT area_of(const PolygonSet& set) {
  std::vector<CGAL::Polygon_with_holes_2<EK>> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  EK::FT area = 0;
  for (const auto& p : parts) {
    area += p.outer_boundary().area();
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) area += h->area();  // holes are clockwise
  }
  return area;
}

}  // namespace

double analytic_wall_volume(const Plan& input) {
  const detail::BuildablePlan buildable = detail::make_buildable(input);
  const Plan& plan = buildable.plan;
  const std::vector<detail::WallFrame> frames =
      detail::make_wall_frames(plan, find_joins(plan), buildable.through_mitre);
  std::vector<Prism> walls, holes;
  std::vector<double> levels;
  for (const detail::WallFrame& f : frames) {
    walls.push_back({to_polygon(detail::exact_footprint(f)), f.base, f.top});
    levels.insert(levels.end(), {f.base, f.top});
    for (const detail::Hole& h : f.holes) {
      holes.push_back({to_polygon(detail::exact_hole_footprint(f, h)), h.z0, h.z1});
      levels.insert(levels.end(), {h.z0, h.z1});
    }
  }
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  EK::FT volume = 0;
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    PolygonSet solid = union_in_slab(walls, levels[k], levels[k + 1]);
    solid.difference(union_in_slab(holes, levels[k], levels[k + 1]));
    volume += area_of(solid) * (EK::FT(levels[k + 1]) - EK::FT(levels[k]));
  }
  return detail::round_to_nearest(volume);
}

}  // namespace roomcad
