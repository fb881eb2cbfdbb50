// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/frames/buildable_plan.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include <fmt/format.h>

#include "core/error.h"
#include "plan/arc_chords.h"
#include "plan/plan_chords.h"
#include "plan/plan_levels.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {
namespace {

// The openings of an arc wall as pieces on its chords: the span [offset, offset + width] along
// the polyline cut at the chords' corners. A piece ending within rounding of its chord's end
// ends there, so that pieces meet exactly on the mitre plane.
void split_openings(const Plan& in, std::size_t wall, const std::vector<std::size_t>& chords,
                    BuildablePlan& out) {
  std::vector<double> start{0.0}, lengths;  // each chord's length as its frame computes it
  for (std::size_t c : chords) {
    const Wall& w = out.plan.walls[c];
    lengths.push_back(std::hypot(w.to.x - w.from.x, w.to.y - w.from.y));
    start.push_back(start.back() + lengths.back());
  }
  const double slack = 1e-12 * start.back();
  for (std::size_t i = 0; i < in.openings.size(); ++i) {
    const Opening& o = in.openings[i];
    if (o.wall != in.walls[wall].id) continue;
    for (std::size_t k = 0; k < chords.size(); ++k) {
      const double length = lengths[k];
      const double from = std::max(o.offset - start[k], 0.0);
      double to = o.offset + o.width - start[k];
      if (to > length && (k + 1 < chords.size() || to <= length + slack))
        to = length;  // past the end: refused
      if (!(to > from)) continue;
      Opening piece = o;
      piece.wall = out.plan.walls[chords[k]].id;
      piece.offset = from, piece.width = to - from;
      // A shape's hole would have to run on through the mitre planes as a rectangle's does;
      // refused rather than cut as separate holes with wall left between them.
      if (!o.shape.empty() && (o.offset - start[k] < 0.0 || to < o.offset + o.width - start[k]))
        throw PreconditionError(
            fmt::format("build_model: opening '{}' has a shape and spans corners of the chords "
                        "of arc wall '{}', which the build does not cut yet; make it rectangular "
                        "or narrow it to one chord",
                        o.id, in.walls[wall].id),
            Code::not_buildable);
      out.plan.openings.push_back(std::move(piece));
      out.opening_of.push_back(i);
      out.through_mitre.push_back({k > 0 && from == 0.0, k + 1 < chords.size() && to == length});
    }
  }
}

}  // namespace

BuildablePlan make_buildable(const Plan& plan) {
  BuildablePlan b;
  b.input_walls = plan.walls.size();
  b.input_openings = plan.openings.size();
  const Plan resolved = with_absolute_heights(plan);
  b.plan = resolved;
  b.plan.walls.clear();
  b.plan.openings.clear();
  const double tolerance = chord_tolerance_of(plan.site);
  std::unordered_map<std::string, std::vector<std::size_t>> chords_of;  // arc wall id -> chords
  std::vector<std::size_t> arcs;
  for (std::size_t i = 0; i < resolved.walls.size(); ++i) {
    const Wall& w = resolved.walls[i];
    std::vector<Wall> chords = chord_walls(w, chord_polyline(w, tolerance));
    if (chords.size() > 1) arcs.push_back(i);
    for (std::size_t k = 0; k < chords.size(); ++k) {
      if (chords.size() > 1) {
        chords[k].id = fmt::format("{} (chord {} of {})", w.id, k + 1, chords.size());
        chords_of[w.id].push_back(b.plan.walls.size());
      }
      b.plan.walls.push_back(std::move(chords[k]));
      b.wall_of.push_back(i);
    }
  }
  for (std::size_t i = 0; i < resolved.openings.size(); ++i) {
    const Opening& o = resolved.openings[i];
    const auto arc = chords_of.find(o.wall);
    if (arc != chords_of.end()) continue;  // below, piece by piece
    b.plan.openings.push_back(o);
    b.opening_of.push_back(i);
    b.through_mitre.push_back({false, false});
  }
  for (std::size_t i : arcs) split_openings(resolved, i, chords_of.at(resolved.walls[i].id), b);
  return b;
}

void label_input_objects(const BuildablePlan& b, std::vector<FaceSoup>& soups) {
  const int walls = static_cast<int>(b.plan.walls.size());
  const int first_slab = slab_object(b.plan, 0);  // slabs are neither split nor reordered
  const int input_first_slab = static_cast<int>(b.input_walls + b.input_openings);
  for (FaceSoup& soup : soups)
    for (SoupFace& f : soup) {
      if (f.object < 0) continue;
      f.object = f.object < walls ? static_cast<int>(b.wall_of[std::size_t(f.object)])
                 : f.object < first_slab
                     ? static_cast<int>(b.input_walls + b.opening_of[std::size_t(f.object - walls)])
                     : input_first_slab + (f.object - first_slab);
    }
}

}  // namespace roomcad::detail
