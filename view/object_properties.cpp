// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/object_properties.h"

#include <fmt/format.h>

#include "plan/field_text.h"
#include "plan/plan_objects.h"

namespace roomcad {
namespace {

/// "name value unit" for each field of an object but its id, from its field table; absent
/// version-2 fields are left out.
template <class Object>
std::vector<std::string> field_lines(const Object& object) {
  std::vector<std::string> lines;
  for (const Field<Object>& f : fields_of<Object>()) {
    if (f.name == "id" || !is_present(object, f)) continue;
    const std::string_view unit = f.unit == Unit::metre    ? " m"
                                  : f.unit == Unit::degree ? " deg"
                                                           : "";
    lines.push_back(fmt::format("{} {}{}", f.name, field_text(object, f), unit));
  }
  return lines;
}

}  // namespace

std::vector<std::string> describe_object(const Plan& plan, std::string_view id) {
  const auto ref = find_object(plan, id);
  if (!ref) return {};
  std::vector<std::string> lines{fmt::format("{} {}", kind_name(plan, *ref), id)};
  visit_object(plan, *ref, [&](const auto& object) {
    for (std::string& line : field_lines(object)) lines.push_back(std::move(line));
  });
  return lines;
}

}  // namespace roomcad
