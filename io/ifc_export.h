// SPDX-License-Identifier: GPL-3.0-or-later
// Writing a plan as an IFC4 model (ISO 16739-1, IFC4 ADD2 TC1), a STEP physical file:
// `roomcad build PLAN -o model.ifc`.
//
// - The spatial tree: IfcProject, IfcSite, IfcBuilding, one IfcBuildingStorey per level (at its
//   elevation), and one storey "ground" at 0 for the objects of no level (a plan without levels
//   has only that one).
// - Each wall an IfcWall with an 'Axis' (its centre line from -> to) and a 'Body': its footprint
//   after its joins (mitred ends, T ends cut back to the face they stop on: export_footprint)
//   extruded by its height, or, for a sloped top, the closed IfcTriangulatedFaceSet of that
//   prism. Joined walls' bodies do not overlap, so their volumes add up to the united solid's.
//   An arc wall (version 2 `arc_extent`) is its chords, as the build makes it: its axis the
//   chord polyline, its body one such item per chord.
// - Each opening an IfcOpeningElement voiding its wall (IfcRelVoidsElement), its body the
//   opening's outline (its `shape` if it has one) extruded through the wall, filled
//   (IfcRelFillsElement) by an IfcDoor or IfcWindow with OverallWidth and OverallHeight. In
//   an arc wall, one item per chord its span crosses (chord_piece_void), as the build cuts it.
// - Each slab an IfcSlab (.FLOOR.), its outline minus its holes extruded by its thickness.
// - Each room (find_rooms, per storey) an IfcSpace: its clear floor extruded to the storey's
//   height, its area as the quantity NetFloorArea.
// - Colours as IfcSurfaceStyle (one per colour); units metres, square and cubic metres, radians.
// - Names and tags are the plan's ids; GlobalIds are derived from them (a 128-bit hash of the
//   kind and id), and the header carries a fixed time stamp: the same plan gives the same bytes.
// A shaped opening in an arc wall is not exported yet: an `unsupported` error names it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad {

/// What an export wrote, for the command's summary and the tests.
struct IfcExportSummary {
  std::size_t storeys = 0;
  std::size_t walls = 0;
  std::size_t openings = 0;  ///< IfcOpeningElement, each filled by one door or window
  std::size_t doors = 0;
  std::size_t windows = 0;
  std::size_t slabs = 0;
  std::size_t spaces = 0;
};

/// @return the IFC text of the plan, named `name` in its header and IfcProject.
/// @pre the plan validates without errors (validation/validate.h).
/// @return an `unsupported` failure naming the first shaped opening in an arc wall. O(n log n)
///   in walls and openings, plus the chords of arc walls and find_rooms per storey.
[[nodiscard]] Result<std::string> format_ifc(const Plan& plan, std::string_view name,
                                             IfcExportSummary* summary = nullptr);

/// Writes format_ifc(plan, file name) to `path` atomically (io/atomic_write.h).
/// @return a failure naming the file and the reason.
Status write_ifc_file(const std::filesystem::path& path, const Plan& plan,
                      IfcExportSummary* summary = nullptr);

}  // namespace roomcad
