// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/scene.h"

#include <algorithm>
#include <cmath>

#include "plan/plan_objects.h"
#include "validation/detail/shapes.h"
#include "validation/rules/door_geometry.h"

namespace roomcad::rules {
namespace {

bool is_testable(const Wall& w) {
  for (const double v : {w.from.x, w.from.y, w.to.x, w.to.y, w.thickness, w.height, w.base})
    if (!std::isfinite(v) || std::fabs(v) > 1e15) return false;
  return w.from != w.to && w.thickness > 0 && w.height > 0;
}

bool is_testable(const Opening& o) {
  for (const double v : {o.offset, o.width, o.height, o.sill})
    if (!std::isfinite(v) || std::fabs(v) > 1e15) return false;
  return o.width > 0 && o.height > 0;
}

}  // namespace

Box2 grown(Box2 box, double margin) {
  box.min_x -= margin, box.min_y -= margin, box.max_x += margin, box.max_y += margin;
  return box;
}

Scene::Scene(const Plan& plan, const Joins& joins, std::vector<bool> usable,
             std::vector<std::optional<std::size_t>> host)
    : plan_(plan), joins_(&joins), usable_(std::move(usable)), host_(std::move(host)) {
  index_walls();
  index_doors();
}

Scene::Scene(const Plan& plan) : plan_(plan) {
  owned_joins_ = std::make_unique<Joins>(find_joins(plan));
  joins_ = owned_joins_.get();
  usable_.resize(plan.walls.size());
  for (std::size_t w = 0; w < plan.walls.size(); ++w) usable_[w] = is_testable(plan.walls[w]);
  index_walls();
  host_.resize(plan.openings.size());
  for (std::size_t i = 0; i < plan.openings.size(); ++i)
    if (const auto w = wall_named(plan.openings[i].wall);
        w && usable_[*w] && is_testable(plan.openings[i]))
      host_[i] = w;
  index_doors();
}

void Scene::index_walls() {
  const detail::Footprints footprints(plan_, *joins_, usable_);
  boxes_.assign(plan_.walls.size(), Box2{});
  for (Box2 b : footprints.boxes()) {
    // Written numbers differ from the doubles by less than an ulp: a relative margin covers them.
    const double scale =
        std::max({std::fabs(b.min_x), std::fabs(b.max_x), std::fabs(b.min_y), std::fabs(b.max_y)});
    b = grown(b, 1e-12 * scale + 1e-12);
    boxes_[b.index] = b;
    usable_boxes_.push_back(b);
  }
  grid_ = BoxGrid(usable_boxes_);
  wall_ids_ = index_by_id(plan_.walls);
}

void Scene::index_doors() {
  openings_of_ = openings_by_wall(plan_);
  doors_of_.assign(plan_.walls.size(), {});
  for (std::size_t i = 0; i < plan_.openings.size(); ++i)
    if (host_[i] && plan_.openings[i].type == OpeningType::door) doors_of_[*host_[i]].push_back(i);
}

std::optional<std::size_t> Scene::wall_named(std::string_view id) const {
  const std::uint32_t w = wall_ids_.find(id);
  if (w == wall_ids_.kNone) return std::nullopt;
  return w;
}

std::vector<Span> Scene::door_holes(std::size_t wall) const {
  std::vector<Span> holes;
  for (const std::size_t i : doors_of_[wall])
    holes.push_back({plan_.openings[i].offset, plan_.openings[i].offset + plan_.openings[i].width});
  std::sort(holes.begin(), holes.end(), [](const Span& a, const Span& b) { return a.lo < b.lo; });
  return holes;
}

}  // namespace roomcad::rules
