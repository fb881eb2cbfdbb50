// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/detail/context.h"

#include "geometry/segment_predicates.h"

namespace roomcad::detail {
namespace {

template <class T>
std::unordered_map<std::string_view, std::size_t> index_by_id(const std::vector<T>& objects) {
  std::unordered_map<std::string_view, std::size_t> index;
  for (std::size_t i = 0; i < objects.size(); ++i) index.emplace(objects[i].id, i);
  return index;
}

std::optional<std::size_t> lookup(const std::unordered_map<std::string_view, std::size_t>& index,
                                  std::string_view id) {
  const auto it = index.find(id);
  if (it == index.end()) return std::nullopt;
  return it->second;
}

}  // namespace

RepairContext::RepairContext(const Plan& plan, double tolerance,
                             const std::vector<Diagnostic>& errors)
    : plan(plan),
      tolerance(tolerance),
      joins(find_joins(plan)),
      openings(openings_by_wall(plan)),
      walls_by_id(index_by_id(plan.walls)),
      openings_by_id(index_by_id(plan.openings)),
      slabs_by_id(index_by_id(plan.slabs)) {
  for (const Diagnostic& d : errors) {
    if (d.code != Code::wall_overlap || d.objects.size() != 2) continue;
    const auto a = wall(d.objects[0]), b = wall(d.objects[1]);
    if (a && b) overlapping_walls.insert(std::minmax(*a, *b));
  }
}

std::optional<std::size_t> RepairContext::wall(std::string_view id) const {
  return lookup(walls_by_id, id);
}
std::optional<std::size_t> RepairContext::opening(std::string_view id) const {
  return lookup(openings_by_id, id);
}
std::optional<std::size_t> RepairContext::slab(std::string_view id) const {
  return lookup(slabs_by_id, id);
}

std::optional<std::string> RepairContext::joined_at(std::size_t w, Point2 end,
                                                    std::size_t other) const {
  const double tol = plan.site.tolerance;
  for (const Join& j : joins.pairs) {
    if (j.a != w && j.b != w) continue;
    const std::size_t x = j.a == w ? j.b : j.a;
    if (x == other) continue;
    const Wall& wx = plan.walls[x];
    if (wx.from == wx.to) continue;
    if (is_near_segment(end, wx.from, wx.to, tol)) return wx.id;
  }
  return std::nullopt;
}

}  // namespace roomcad::detail
