// SPDX-License-Identifier: GPL-3.0-or-later
// Equal planes of a PlaneSet (exact_planes.h): are_same_plane and PlaneSet::find_equal_planes.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/flat_index.h"
#include "exact/interval_sign.h"
#include "solid/detail/general_path/exact_planes.h"

namespace roomcad::detail {
namespace {

// Sign-free invariants of a plane for grouping equal planes: |d| / |n|, then |a|, |b|, |c|
// over |n|, as intervals (equal planes have equal invariants, so theirs overlap).
std::array<Interval, 4> invariants(const std::array<Interval, 4>& c) {
  const Interval norm = CGAL::sqrt(CGAL::square(c[0]) + CGAL::square(c[1]) + CGAL::square(c[2]));
  return {CGAL::abs(c[3]) / norm, CGAL::abs(c[0]) / norm, CGAL::abs(c[1]) / norm,
          CGAL::abs(c[2]) / norm};
}

}  // namespace

bool are_same_plane(const PlaneSet& set, PlaneId a, PlaneId b) {
  if (a == b) return true;
  const PlaneRecipe& ra = set.recipe(a);
  const PlaneRecipe& rb = set.recipe(b);
  if (ra.kind == PlaneRecipe::Kind::axis && rb.kind == PlaneRecipe::Kind::axis)
    return ra.v[0] == rb.v[0] && ra.v[1] == rb.v[1] && ra.v[2] == rb.v[2];
  {
    const IntervalScope upward;
    const auto& p = set.approx(a);
    const auto& q = set.approx(b);
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) {
        const int s = interval_sign(p[i] * q[j] - p[j] * q[i]);
        if (s == 1 || s == -1) return false;
      }
  }
  const auto& p = set.exact(a);
  const auto& q = set.exact(b);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      if (!(p[i] * q[j] - p[j] * q[i]).is_zero()) return false;
  return true;
}

std::vector<PlaneRef> PlaneSet::find_equal_planes() const {
  const std::size_t n = recipes_.size();
  // Axis planes with the same recipe are the same plane (are_same_plane compares axis planes
  // by their recipes): hashed first, so the sweep below sees one of each, the lowest id.
  // Every face of an axis-aligned wall lies on one, repeated by each wall along the line.
  std::vector<PlaneId> rep_of(n), swept;
  FlatIndex<std::array<std::uint64_t, 3>> axis_first(n);
  for (PlaneId id = 0; id < n; ++id) {
    const PlaneRecipe& r = recipes_[id];
    rep_of[id] = id;
    if (r.kind == PlaneRecipe::Kind::axis && !std::isnan(r.v[1]) && !std::isnan(r.v[2])) {
      // + 0.0: -0.0 and 0.0 are one coordinate, as == has them.
      const std::array<std::uint64_t, 3> key{std::uint64_t(r.v[0]),
                                             std::bit_cast<std::uint64_t>(r.v[1] + 0.0),
                                             std::bit_cast<std::uint64_t>(r.v[2] + 0.0)};
      const auto [first, fresh] = axis_first.try_emplace(key, id);
      rep_of[id] = first;
      if (!fresh) continue;
    }
    swept.push_back(id);
  }
  std::vector<std::array<Interval, 4>> inv(n);
  {
    const IntervalScope upward;
    for (const PlaneId id : swept) inv[id] = invariants(approx_[id]);
  }
  std::vector<PlaneId> order = swept;
  // Planes in order of their lowest possible |d| / |n|; equal planes overlap in every invariant.
  std::stable_sort(order.begin(), order.end(),
                   [&](PlaneId x, PlaneId y) { return inv[x][0].inf() < inv[y][0].inf(); });
  std::vector<PlaneRef> group(n);
  std::vector<PlaneId> active;  // representatives whose |d| / |n| may still overlap
  for (PlaneId id : order) {
    const double lo = inv[id][0].inf();
    active.erase(std::remove_if(active.begin(), active.end(),
                                [&](PlaneId r) { return inv[r][0].sup() < lo; }),
                 active.end());
    PlaneId found = id;
    for (PlaneId r : active) {
      bool overlap = true;
      for (std::size_t k = 1; k < 4 && overlap; ++k) overlap = do_overlap(inv[id][k], inv[r][k]);
      if (overlap && are_same_plane(*this, id, r)) {
        found = r;
        break;
      }
    }
    rep_of[id] = found;
    if (found == id) active.push_back(id);
  }
  for (PlaneId id = 0; id < n; ++id)
    rep_of[id] = rep_of[rep_of[id]];  // a hashed repeat: its first's
  // The group's representative is its lowest id, so the result does not depend on the sort.
  std::vector<PlaneId> lowest(n, PlaneId(n));
  for (PlaneId id = 0; id < n; ++id) lowest[rep_of[id]] = std::min(lowest[rep_of[id]], id);
  for (PlaneId id = 0; id < n; ++id) {
    const PlaneId rep = lowest[rep_of[id]];
    group[id] = {rep, rep == id ? 1 : dot_normals(*this, {id, 1}, {rep, 1})};
  }
  return group;
}

}  // namespace roomcad::detail
