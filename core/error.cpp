// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/error.h"

#include <ostream>

namespace roomcad {

std::ostream& operator<<(std::ostream& out, const Error& error) {
  out << error.code << ": " << error.message;
  if (error.location)
    out << " (at " << error.location->file << ':' << error.location->line << ':'
        << error.location->column << ' ' << error.location->pointer << ')';
  return out;
}

}  // namespace roomcad
