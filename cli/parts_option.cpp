// The --parts list of the commands that build the model.
#include "cli/parts_option.h"

#include <sstream>

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

}  // namespace roomcad::cli
