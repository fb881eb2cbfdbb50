// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/detail/slabs.h"

#include <algorithm>

#include <fmt/format.h>

#include "geometry/polygon_predicates.h"
#include "plan/plan_levels.h"
#include "repair/detail/frame_box.h"

namespace roomcad::detail {

Attempt propose_slab_cut(const RepairContext& ctx, const Diagnostic& finding) {
  const auto a = finding.objects.size() == 2 ? ctx.slab(finding.objects[0]) : std::nullopt;
  const auto b = finding.objects.size() == 2 ? ctx.slab(finding.objects[1]) : std::nullopt;
  if (!a || !b) return refused("not a pair of slabs");
  const Slab& first = ctx.plan.slabs[std::min(*a, *b)];
  const Slab& later = ctx.plan.slabs[std::max(*a, *b)];
  const double first_top = top_z(ctx.plan, first), later_top = top_z(ctx.plan, later);
  const Extent kept{first_top - first.thickness, first_top};
  const double moves = kept.excess({later_top - later.thickness, later_top});
  if (moves > ctx.tolerance) return refused(too_far(moves, ctx.tolerance));
  const std::vector<Area> rest =
      area_difference(later.outline, later.holes, first.outline, first.holes);
  Proposal p;
  if (rest.empty()) {
    p.edits.push_back(
        {later.id, RepairChange::remove, {{"outline", later.outline}}, {}, {}, moves});
    return {{std::move(p)}, {}};
  }
  if (rest.size() > 1 || rest[0].holes != later.holes)
    return refused(
        fmt::format("cutting slab '{}' back would leave it in {} pieces or change its "
                    "holes",
                    later.id, rest.size()));
  p.edits.push_back({later.id,
                     RepairChange::cut,
                     {{"outline", later.outline}},
                     {{"outline", rest[0].outline}},
                     {},
                     moves});
  return {{std::move(p)}, {}};
}

}  // namespace roomcad::detail
