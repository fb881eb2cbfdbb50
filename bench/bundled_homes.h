// SPDX-License-Identifier: GPL-3.0-or-later
// The homes the build benchmarks time: the plans of examples/sweethome3d/ (or other folders
// given), then the generated 504-wall tower of six storeys (testing/tower_plan.h).
#pragma once

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/plan_json.h"
#include "testing/tower_plan.h"

namespace roomcad::bench {

struct NamedPlan {
  std::string name;  ///< the plan file's stem, or "tower"
  Plan plan;
};

/// @param[in] dirs  folders of plan files; none: examples/sweethome3d/
/// @return the .json plans of each folder in order of their names, then the tower; a plan
///         that does not read is left out with a line on stderr naming the file and why.
inline std::vector<NamedPlan> read_homes(std::vector<std::filesystem::path> dirs) {
  if (dirs.empty())
    dirs.push_back(std::filesystem::path(ROOMCAD_SOURCE_DIR) / "examples" / "sweethome3d");
  std::vector<NamedPlan> homes;
  for (const auto& dir : dirs) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      Result<Plan> plan = read_plan_file(file);
      if (!plan) {
        std::fprintf(stderr, "%s: %s\n", file.c_str(), plan.message().c_str());
        continue;
      }
      homes.push_back({file.stem().string(), std::move(plan).value()});
    }
  }
  homes.push_back({"tower", samples::make_tower_plan({})});
  return homes;
}

}  // namespace roomcad::bench
