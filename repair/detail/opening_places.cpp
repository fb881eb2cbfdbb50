// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/detail/opening_places.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "plan/plan_levels.h"
#include "repair/detail/frame_box.h"
#include "repair/detail/proposal.h"

namespace roomcad::detail {
namespace {

/// Where an opening stands: the ends of its span on the centre line, its bottom, in long
/// double so that the rounding of a new offset or sill can be measured.
struct Place {
  long double start_x, start_y, end_x, end_y, bottom;
};

Place place_of(const Plan& plan, const Wall& host, const Opening& o) {
  const long double length = std::hypot(static_cast<long double>(host.to.x) - host.from.x,
                                        static_cast<long double>(host.to.y) - host.from.y);
  const long double ux = (static_cast<long double>(host.to.x) - host.from.x) / length;
  const long double uy = (static_cast<long double>(host.to.y) - host.from.y) / length;
  const long double a = o.offset, b = static_cast<long double>(o.offset) + o.width;
  return {host.from.x + a * ux, host.from.y + a * uy, host.from.x + b * ux, host.from.y + b * uy,
          static_cast<long double>(base_z(plan, host)) + o.sill};
}

/// The opening's offset and sill on `host` for `place`, and how far rounding them moves it.
struct Fit {
  double offset, sill, rounding;
  bool reversed;
};

std::optional<Fit> fit_on(const Plan& plan, const Wall& host, const Opening& o, const Place& p) {
  const long double length = std::hypot(static_cast<long double>(host.to.x) - host.from.x,
                                        static_cast<long double>(host.to.y) - host.from.y);
  const long double ux = (static_cast<long double>(host.to.x) - host.from.x) / length;
  const long double uy = (static_cast<long double>(host.to.y) - host.from.y) / length;
  const auto s = [&](long double x, long double y) {
    return (x - host.from.x) * ux + (y - host.from.y) * uy;
  };
  const long double s0 = s(p.start_x, p.start_y), s1 = s(p.end_x, p.end_y);
  const bool reversed = s1 < s0;
  const long double start = reversed ? s1 : s0;
  const long double sill = p.bottom - base_z(plan, host);
  const double offset = static_cast<double>(start), new_sill = static_cast<double>(sill);
  const bool fits = offset >= 0 && offset + o.width <= wall_length(host) && new_sill >= 0 &&
                    new_sill + o.height <= host.height;
  if (!fits) return std::nullopt;
  const long double rounding = std::fabs(offset - start) + std::fabs(new_sill - sill);
  return Fit{offset, new_sill, static_cast<double>(rounding), reversed};
}

Polygon mirrored(const Polygon& shape) {
  Polygon out;
  for (auto it = shape.rbegin(); it != shape.rend(); ++it) out.push_back({1.0 - it->x, it->y});
  return out;
}

RepairEdit opening_edit(const Opening& o, const Wall& host, const Fit& fit) {
  RepairEdit e{o.id, RepairChange::move, {}, {}, {}, fit.rounding};
  record_field(e, "wall", o.wall, host.id);
  record_field(e, "offset", o.offset, fit.offset);
  record_field(e, "sill", o.sill, fit.sill);
  if (fit.reversed) {  // the wall runs the other way: the door keeps its side and hand
    const Hinge hinge = o.hinge == Hinge::left ? Hinge::right : Hinge::left;
    const Swing swing = o.swing == Swing::in ? Swing::out : Swing::in;
    record_field(e, "hinge", std::string(to_string(o.hinge)), std::string(to_string(hinge)));
    record_field(e, "swing", std::string(to_string(o.swing)), std::string(to_string(swing)));
    if (!o.shape.empty()) record_field(e, "shape", o.shape, mirrored(o.shape));
  }
  return e;
}

/// @return how far opening `o`, placed by `fit`, reaches out of the one of `openings`
///         (rectangles) that holds it best: 0 inside one; infinity when there is none.
double reach_out_of(const Plan& plan, const std::vector<std::size_t>& openings, const Opening& o,
                    const Fit& fit) {
  const Extent along{fit.offset, fit.offset + o.width}, up{fit.sill, fit.sill + o.height};
  double best = INFINITY;
  for (const std::size_t i : openings) {
    const Opening& h = plan.openings[i];
    if (!h.shape.empty()) continue;
    const Extent h_along{h.offset, h.offset + h.width}, h_up{h.sill, h.sill + h.height};
    best = std::min(best, std::hypot(h_along.excess(along), h_up.excess(up)));
  }
  return best;
}

}  // namespace

Placement place_openings(const Plan& plan, const std::vector<std::size_t>& openings,
                         const Wall& old_host, const std::optional<Wall>& new_host,
                         const Wall& other, const std::vector<std::size_t>& others_openings,
                         double tolerance) {
  Placement out;
  // How far the old host's centre line lies off the other's (0 on one line): a rehosted
  // opening moves by as much.
  const LineFrame frame = line_frame(other);
  const double off = std::max(std::fabs(frame.n(old_host.from)), std::fabs(frame.n(old_host.to)));
  const double spill = std::max(off - (other.thickness - old_host.thickness) / 2, 0.0);
  const bool same_prism = old_host.thickness == other.thickness && off <= tolerance;
  const bool within_width = spill <= tolerance;
  for (const std::size_t i : openings) {
    const Opening& o = plan.openings[i];
    const Place place = place_of(plan, old_host, o);
    std::optional<Fit> fit;
    if (new_host && (fit = fit_on(plan, *new_host, o, place))) {
      RepairEdit e = opening_edit(o, *new_host, *fit);
      if (!e.new_values.empty()) out.edits.push_back(std::move(e));
      continue;
    }
    // The hole is already cut by one of the other wall's openings (a split copy of it).
    if (within_width && o.shape.empty() && (fit = fit_on(plan, other, o, place))) {
      const double reach = std::hypot(reach_out_of(plan, others_openings, o, *fit), spill);
      if (reach <= tolerance) {
        out.edits.push_back({o.id, RepairChange::remove, {{"wall", o.wall}}, {}, {}, reach});
        continue;
      }
    }
    if (!same_prism || !(fit = fit_on(plan, other, o, place))) {
      out.refusal = fmt::format("opening '{}' would stand on no wall", o.id);
      return out;
    }
    fit->rounding += off;
    RepairEdit e = opening_edit(o, other, *fit);
    if (!e.new_values.empty()) out.edits.push_back(std::move(e));
  }
  return out;
}

}  // namespace roomcad::detail
