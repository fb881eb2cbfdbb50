// duplicate_id (ids are unique across ALL objects of a plan) and unknown_reference.
#include <algorithm>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"

namespace roomcad::detail {
namespace {

struct IdUse {
  std::string_view id;
  std::string label;  ///< "wall #3"
};

std::vector<IdUse> collect_ids(const Plan& plan) {
  std::vector<IdUse> uses;
  const auto add = [&uses](const std::string& id, std::string_view list, std::size_t i) {
    if (!id.empty()) uses.push_back({id, fmt::format("{}[{}]", list, i)});
  };
  for (std::size_t i = 0; i < plan.walls.size(); ++i) add(plan.walls[i].id, "walls", i);
  for (std::size_t i = 0; i < plan.openings.size(); ++i) add(plan.openings[i].id, "openings", i);
  for (std::size_t i = 0; i < plan.lights.size(); ++i) add(plan.lights[i].id, "lights", i);
  for (std::size_t i = 0; i < plan.cameras.size(); ++i) add(plan.cameras[i].id, "cameras", i);
  return uses;
}

void report_duplicates(const Plan& plan, Report& report) {
  std::vector<IdUse> uses = collect_ids(plan);
  std::stable_sort(uses.begin(), uses.end(),
                   [](const IdUse& a, const IdUse& b) { return a.id < b.id; });
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].id == uses[i].id) ++j;
    if (j - i > 1) {
      std::vector<std::string> labels;
      for (std::size_t k = i; k < j; ++k) labels.push_back(uses[k].label);
      report.add(make_diagnostic(
          Severity::error, "duplicate_id", {std::string(uses[i].id)},
          fmt::format("id '{}' is used by {} objects ({}); ids must be unique in the plan.",
                      uses[i].id, j - i, fmt::join(labels, ", ")),
          fmt::format("rename all but one of them, e.g. {} to '{}-2'", labels[1], uses[i].id)));
    }
    i = j;
  }
}

}  // namespace

void check_ids(const Plan& plan, Usable& usable, Report& report) {
  report_duplicates(plan, report);
  std::unordered_map<std::string_view, std::size_t> walls;
  for (std::size_t i = plan.walls.size(); i-- > 0;) walls[plan.walls[i].id] = i;  // first wins
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    const Opening& o = plan.openings[i];
    const auto found = walls.find(o.wall);
    if (found == walls.end()) {
      usable.host[i].reset();
      report.add(make_diagnostic(
          Severity::error, "unknown_reference", {o.id},
          fmt::format("{} names wall '{}', which is not in the plan.", name_of(o), o.wall),
          plan.walls.empty()
              ? std::string("add the wall it belongs to, or delete the opening")
              : fmt::format("set its wall to the id of an existing wall, e.g. '{}'",
                            plan.walls.front().id)));
      continue;
    }
    if (usable.host[i] && usable.walls[found->second]) usable.host[i] = found->second;
    else usable.host[i].reset();
  }
}

}  // namespace roomcad::detail
