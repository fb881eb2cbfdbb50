// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/detail/proposal.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/assert.h"
#include "core/box.h"
#include "plan/plan_objects.h"

namespace roomcad::detail {
namespace {

template <class T>
const T& as(const RepairValue& value) {
  const T* v = std::get_if<T>(&value);
  RC_ASSERT(v != nullptr, "a field value of the type its key takes");
  return *v;
}

void set(Wall& w, const std::string& key, const RepairValue& v) {
  if (key == "from") w.from = as<Point2>(v);
  else if (key == "to") w.to = as<Point2>(v);
  else if (key == "base") w.base = as<double>(v);
  else if (key == "height") w.height = as<double>(v);
  else RC_ASSERT(false, "a wall field repair writes");
}

void set(Opening& o, const std::string& key, const RepairValue& v) {
  if (key == "wall") o.wall = as<std::string>(v);
  else if (key == "offset") o.offset = as<double>(v);
  else if (key == "width") o.width = as<double>(v);
  else if (key == "height") o.height = as<double>(v);
  else if (key == "sill") o.sill = as<double>(v);
  else if (key == "hinge") o.hinge = as<std::string>(v) == "left" ? Hinge::left : Hinge::right;
  else if (key == "swing") o.swing = as<std::string>(v) == "in" ? Swing::in : Swing::out;
  else if (key == "shape") o.shape = as<Polygon>(v);
  else RC_ASSERT(false, "an opening field repair writes");
}

void set(Slab& s, const std::string& key, const RepairValue& v) {
  RC_ASSERT(key == "outline", "a slab field repair writes");
  s.outline = as<Polygon>(v);
}

template <class T>
void set(T&, const std::string&, const RepairValue&) {
  RC_ASSERT(false, "repair edits only walls, openings and slabs");
}

double box_surface(double a, double b, double c) { return 2 * (a * b + b * c + c * a); }

double surface_bound(const Plan&, const Wall& w) {
  return box_surface(std::hypot(w.to.x - w.from.x, w.to.y - w.from.y) + w.thickness, w.thickness,
                     highest_height(w));
}
double surface_bound(const Plan& plan, const Opening& o) {
  const Wall* host = find_wall(plan, o.wall);
  return box_surface(o.width, o.height, host ? host->thickness : 0.0);
}
double surface_bound(const Plan&, const Slab& s) {
  Box2 box = empty_box2();
  for (const Point2& c : s.outline) add_point(box, c.x, c.y);
  return box_surface(box.max_x - box.min_x, box.max_y - box.min_y, s.thickness);
}
template <class T>
double surface_bound(const Plan&, const T&) {
  return 0.0;
}

}  // namespace

double volume_slack(const Plan& plan, const Proposal& p) {
  double move = 0, area = 0;
  for (const RepairEdit& e : p.edits) {
    move = std::max(move, e.moves);
    const std::optional<ObjectRef> ref = find_object(plan, e.object);
    if (!ref) continue;
    visit_object(plan, *ref, [&](const auto& object) { area += surface_bound(plan, object); });
  }
  return move * area;
}

FindingKey key_of(const Diagnostic& finding) { return {finding.code, finding.objects}; }

void apply_edit(Plan& plan, const RepairEdit& edit) {
  const std::optional<ObjectRef> ref = find_object(plan, edit.object);
  RC_ASSERT(ref.has_value(), "an edit of an object of the plan");
  if (edit.change == RepairChange::remove) {
    erase_object(plan, *ref);
    return;
  }
  visit_object(plan, *ref, [&](auto& object) {
    for (const auto& [key, value] : edit.new_values) set(object, key, value);
  });
}

std::string too_far(double move, double tolerance) {
  return fmt::format("needs a move of {:.3f} m, more than the tolerance {} m", move, tolerance);
}

}  // namespace roomcad::detail
