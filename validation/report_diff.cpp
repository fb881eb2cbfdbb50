#include "validation/report_diff.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace roomcad {
namespace {

/// An error's identity across an edit.
using ErrorKey = std::pair<Code, std::vector<std::string>>;

ErrorKey key_of(const Diagnostic& d) {
  std::vector<std::string> ids = d.objects;
  std::sort(ids.begin(), ids.end());
  return {d.code, std::move(ids)};
}

}  // namespace

Report introduced_errors(const Report& before, const Report& after) {
  std::map<ErrorKey, int> budget;
  for (const Diagnostic& d : before.items)
    if (d.severity == Severity::error) ++budget[key_of(d)];
  Report fresh;
  for (const Diagnostic& d : after.items) {
    if (d.severity != Severity::error) continue;
    int& left = budget[key_of(d)];
    if (left > 0) --left;
    else fresh.add(d);
  }
  return fresh;
}

}  // namespace roomcad
