// SPDX-License-Identifier: GPL-3.0-or-later
// check_rules: the rule sets' rules on what validate() found, in a fixed order.
#include <future>

#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"
#include "validation/rules/rules.h"

namespace roomcad {
namespace rules {

Diagnostic make_finding(const Context& cx, Code code, std::vector<std::string> objects,
                        std::string message, std::string fix, std::vector<FixEdit> edits,
                        std::optional<Where> where) {
  Diagnostic d = detail::make_diagnostic(cx.severity(code), code, std::move(objects),
                                         std::move(message), std::move(fix), std::move(where));
  d.edits = std::move(edits);
  return d;
}

Where room_where(const Room& room) {
  const Box2 b = room_box(room);
  return detail::box_where(b.min_x, b.min_y, b.max_x, b.max_y);
}

}  // namespace rules

namespace detail {

void check_rules(const Plan& plan, const Joins& joins, const Usable& usable,
                 const RuleSet& rule_set, const std::vector<Room>* whole_rooms, Report& report) {
  const rules::Context cx(plan, joins, usable, rule_set, whole_rooms);
  const rules::Scene scene(plan, joins, usable.walls, usable.host);
  // Objects on one thread, rooms on the other; each writes its own report, joined in order.
  Report objects;
  std::future<void> object_rules = std::async(std::launch::async, [&] {
    rules::check_doors(cx, scene, objects);
    rules::check_windows(cx, scene, objects);
    rules::check_duplicates(cx, scene, objects);
  });
  Report rooms;
  rules::check_reachability(cx, scene, rooms);
  rules::check_turning_circles(cx, scene, rooms);
  rules::check_passages(cx, scene, rooms);
  rules::check_escape(cx, scene, rooms);
  object_rules.get();
  report.append(objects);
  report.append(rooms);
}

}  // namespace detail
}  // namespace roomcad
