// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/fix_search.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "core/error.h"
#include "geometry/segment_predicates.h"
#include "validation/fix_edits.h"
#include "validation/report_diff.h"
#include "validation/validate.h"

namespace roomcad::rules {
namespace {

ValidateOptions local_options() {
  ValidateOptions o;
  o.room_warnings = false;
  o.unknown_field_warnings = false;
  return o;
}

}  // namespace

Heights heights_of(const Wall& w) { return {w.base, w.base + highest_height(w)}; }

Heights heights_of(const Plan& plan, const std::vector<std::size_t>& walls) {
  Heights band = heights_of(plan.walls[walls.front()]);
  for (const std::size_t w : walls) {
    const Heights h = heights_of(plan.walls[w]);
    band = {std::min(band.low, h.low), std::max(band.high, h.high)};
  }
  return band;
}

Neighbourhood::Neighbourhood(const Scene& scene, const Box2& box, Heights heights) {
  const Plan& plan = scene.plan();
  std::set<std::size_t> walls;
  for (const std::size_t w : scene.walls_near(box)) {
    const Heights h = heights_of(plan.walls[w]);
    if (h.low > heights.high || h.high < heights.low) continue;  // another storey's
    walls.insert(w);
    for (const std::size_t partner : scene.walls_near(scene.wall_box(w)))
      if (scene.joins().are_joined(w, partner)) walls.insert(partner);
  }
  plan_.site = plan.site;
  std::vector<std::size_t> openings;
  for (const std::size_t w : walls) {
    plan_.walls.push_back(plan.walls[w]);
    openings.insert(openings.end(), scene.openings_of(w).begin(), scene.openings_of(w).end());
  }
  std::sort(openings.begin(), openings.end());  // in plan order, as validation would see them
  for (const std::size_t i : openings) plan_.openings.push_back(plan.openings[i]);
  before_ = validate(plan_, local_options());
}

std::optional<Plan> Neighbourhood::try_edits(const std::vector<FixEdit>& edits) const {
  Plan edited = plan_;
  try {
    apply_fix_edits(edited, edits);
  } catch (const PreconditionError&) {
    return std::nullopt;
  }
  if (!introduced_errors(before_, validate(edited, local_options())).items.empty())
    return std::nullopt;
  return edited;
}

std::string number_text(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value == 0.0 ? 0.0 : value).ptr;
  return std::string(text, end);
}

double centimetres_up(double value) { return std::ceil(value * 100 - 1e-7) / 100; }
double centimetres_down(double value) { return std::floor(value * 100 + 1e-7) / 100; }

std::string point_text(Point2 p) { return number_text(p.x) + ',' + number_text(p.y); }

std::vector<FixEdit> move_wall_edits(const Scene& scene, std::size_t wall, Point2 by) {
  const Plan& plan = scene.plan();
  const Wall& w = plan.walls[wall];
  const auto moved = [&](Point2 p) { return Point2{p.x + by.x, p.y + by.y}; };
  std::vector<FixEdit> edits{
      set_edit(w.id, {{"from", point_text(moved(w.from))}, {"to", point_text(moved(w.to))}})};
  for (const std::size_t x : scene.walls_near(scene.wall_box(wall))) {
    if (x == wall || !scene.joins().are_joined(wall, x)) continue;
    const Wall& other = plan.walls[x];
    std::vector<std::pair<std::string, std::string>> ends;
    for (const auto& [key, end] : {std::pair{"from", other.from}, std::pair{"to", other.to}})
      if (is_near_segment(end, w.from, w.to, plan.site.tolerance))
        ends.emplace_back(key, point_text(moved(end)));
    if (!ends.empty()) edits.push_back(set_edit(other.id, std::move(ends)));
  }
  return edits;
}

FixEdit set_edit(std::string id, std::vector<std::pair<std::string, std::string>> fields) {
  FixEdit e;
  e.op = FixEdit::Op::set;
  e.id = std::move(id);
  e.fields = std::move(fields);
  return e;
}

}  // namespace roomcad::rules
