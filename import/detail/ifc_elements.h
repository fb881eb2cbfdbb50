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
  /// IFC wall -> indices of the plan walls it became (two for a gable)
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> walls_of;
  std::unordered_map<std::uint32_t, std::size_t> slab_of;  ///< IFC slab -> plan slab index
  std::unordered_set<std::uint32_t> read;                  ///< entities in the plan
  std::unordered_set<std::uint32_t> skipped;               ///< entities left out
  /// Entities approximated -> the largest measured distance, metres, from the file's geometry.
  std::unordered_map<std::uint32_t, double> approximated;
  std::unordered_set<std::uint32_t> unmeasured;  ///< approximated by a distance not measured
  std::size_t walls = 0;                         ///< IFC walls read
  std::size_t openings = 0;                      ///< IFC openings read
  std::size_t slabs = 0;                         ///< IFC slabs read

  /// @return `name` if it is non-empty and unused, else `prefix-<instance number>`; marks it used.
  std::string unique_id(std::string_view name, std::string_view prefix, std::uint32_t entity);
  /// Adds a warning naming the entity ("#12 IFCWALL 'name': ..."), and tallies the entity as
  /// skipped (import_skipped_*, import_zero_length_wall) or approximated, distance unmeasured.
  void warn(Code code, const step::Instance& entity, std::string_view what,
            std::vector<std::string> objects = {});
  /// Adds an import_approximated warning for an approximation within `metres` of the file.
  void approximate(const step::Instance& entity, std::string_view what, double metres,
                   std::vector<std::string> objects = {});
  /// Adds a warning naming the entity, without tallying it.
  void add_warning(Code code, const step::Instance& entity, std::string_view what,
                   std::vector<std::string> objects);
  /// @return metres rounded to the micrometre: what a plan file shows, and no float dust.
  [[nodiscard]] double metres(double file_units) const;
};

/// Reads IfcWall, IfcWallStandardCase and IfcWallElementedCase whose body is a vertical
/// extrusion: the centre line from the 'Axis' (or the footprint's long side), the thickness and
/// the height from the footprint, checked against the material layer set. O(walls).
void import_walls(ImportState& state);

/// Reads each IfcOpeningElement voiding an imported wall (IfcRelVoidsElement): its extent along
/// the wall and in height, its outline as a `shape` where it is not a rectangle, its type from
/// the IfcDoor or IfcWindow filling it (IfcRelFillsElement). One voiding an imported slab is a
/// hole in it where its footprint lies strictly inside the slab's outline and clear of its
/// other holes. Run after import_walls and import_slabs. O(openings * holes + relations).
void import_openings(ImportState& state);

/// Reads each IfcCurtainWall as a straight wall over the footprint and height of its own body
/// and its aggregated IfcMember and IfcPlate parts, as thick as they are deep (0.1 m if they are
/// flat), its aggregated IfcDoor and IfcWindow parts as openings. O(parts' bodies).
void import_curtain_walls(ImportState& state);

/// Sets the plan's site.location from the first IfcSite's RefLatitude and RefLongitude (with
/// the longitude's nautical time zone, IFC having none) and site.north from the 3D model
/// context's TrueNorth. O(file).
void import_site(ImportState& state);

/// Reads each IfcSlab whose body is a vertical extrusion of a polyline profile. O(slabs).
void import_slabs(ImportState& state);

}  // namespace roomcad::ifc
