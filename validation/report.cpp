// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/report.h"

#include <algorithm>

namespace roomcad {

std::size_t Report::error_count() const {
  return static_cast<std::size_t>(
      std::count_if(items.begin(), items.end(),
                    [](const Diagnostic& d) { return d.severity == Severity::error; }));
}

std::size_t Report::warning_count() const { return items.size() - error_count(); }

bool Report::ok() const { return error_count() == 0; }

void Report::append(const Report& other) {
  items.insert(items.end(), other.items.begin(), other.items.end());
}

}  // namespace roomcad
