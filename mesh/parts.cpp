// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "mesh/parts.h"

namespace roomcad {

Result<Parts> parse_parts(std::string_view list) {
  Parts parts{false, false, false, false};
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view name = list.substr(start, comma - start);
    if (name == "walls") parts.walls = true;
    else if (name == "slabs") parts.slabs = true;
    else if (name == "floor") parts.floor = true;
    else if (name == "fixtures") parts.fixtures = true;
    else
      return Result<Parts>::failure(
          Code::usage_error,
          fmt::format("--parts '{}': '{}' is not one of {}", list, name, kPartNames));
    start = comma + 1;
  }
  return parts;
}

}  // namespace roomcad
