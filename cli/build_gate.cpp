// The --parts list and the validation gate of the commands that build the model.
#include "cli/build_gate.h"

#include <cstdio>
#include <sstream>

#include "cli/plan_loading.h"
#include "validation/report_format.h"
#include "validation/validate.h"

namespace roomcad::cli {

bool parse_parts(const std::string& list, Parts& parts, std::string& bad) {
  parts = {false, false, false};
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (name == "walls") parts.walls = true;
    else if (name == "floor") parts.floor = true;
    else if (name == "fixtures") parts.fixtures = true;
    else return bad = name, false;
  }
  return parts.walls || parts.floor || parts.fixtures || (bad = list, false);
}

bool passes_validation(std::string_view command, const std::string& plan_path, const Plan& plan,
                       bool force) {
  const Report report = validate(plan);
  if (report.items.empty()) return true;
  std::fputs(format_report_text(report, use_colour(stderr)).c_str(), stderr);
  if (report.ok()) return true;
  std::fprintf(stderr, "roomcad %.*s: %s: %s%s\n", static_cast<int>(command.size()),
               command.data(), plan_path.c_str(), format_report_summary(report).c_str(),
               force ? "; going on anyway (--force)" : "; stopped (use --force to try)");
  return force;
}

}  // namespace roomcad::cli
