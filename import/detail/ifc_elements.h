// SPDX-License-Identifier: GPL-3.0-or-later
// The IFC importer's steps (import/ifc_import.h): walls, openings with their doors and
// windows, and slabs, read into a plan that is being built, with a warning for every element
// or part of one that the plan cannot hold.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "import/detail/ifc_geometry.h"
#include "io/step_file.h"
#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad::ifc {

/// What the steps share: the file, its geometry, and the plan so far.
struct ImportState {
  ImportState(const step::File& f)
      : file(f), geometry(f), metres_per_unit(geometry.metres_per_unit()) {}

  const step::File& file;
  Geometry geometry;
  double metres_per_unit = 1.0;
  Plan plan;
  Report warnings;
  std::unordered_set<std::string> ids;                              ///< every id given so far
  std::unordered_set<std::uint32_t> handled;                        ///< imported or warned about
  std::unordered_map<std::uint32_t, std::string> level_of_element;  ///< element -> level id
  std::unordered_map<std::string, double> elevation_of_level;       ///< level id -> metres
  std::unordered_map<std::uint32_t, std::size_t> wall_of;           ///< IFC wall -> plan wall index
  std::size_t walls = 0;                                            ///< IFC walls read
  std::size_t openings = 0;                                         ///< IFC openings read
  std::size_t slabs = 0;                                            ///< IFC slabs read

  /// @return `name` if it is non-empty and unused, else `prefix-<instance number>`; marks it used.
  std::string unique_id(std::string_view name, std::string_view prefix, std::uint32_t entity);
  /// Adds a warning naming the entity ("#12 IFCWALL 'name': ...").
  void warn(Code code, const step::Instance& entity, std::string_view what,
            std::vector<std::string> objects = {});
  /// @return metres rounded to the micrometre: what a plan file shows, and no float dust.
  [[nodiscard]] double metres(double file_units) const;
};

/// Reads IfcWall, IfcWallStandardCase and IfcWallElementedCase whose body is a vertical
/// extrusion: the centre line from the 'Axis' (or the footprint's long side), the thickness and
/// the height from the footprint, checked against the material layer set. O(walls).
void import_walls(ImportState& state);

/// Reads each IfcOpeningElement voiding an imported wall (IfcRelVoidsElement): its extent along
/// the wall and in height, its outline as a `shape` where it is not a rectangle, its type from
/// the IfcDoor or IfcWindow filling it (IfcRelFillsElement). O(openings + relations).
void import_openings(ImportState& state);

/// Reads each IfcSlab whose body is a vertical extrusion of a polyline profile. O(slabs).
void import_slabs(ImportState& state);

}  // namespace roomcad::ifc
