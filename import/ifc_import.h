// SPDX-License-Identifier: GPL-3.0-or-later
// Importing IFC models (IFC2X3 and IFC4 STEP physical files) as plans:
// `roomcad import model.ifc -o plan.json`.
//
// The common subset of what BIM tools write:
// - IfcBuildingStorey as levels: id its Name, elevation its placement's height, height up to
//   the next storey (the last: up to its highest wall, or 2.8 m);
// - IfcWall, IfcWallStandardCase (and IfcWallElementedCase) whose 'Body' is a vertical
//   extrusion of a rectangle, circle or closed curve (polylines, IfcIndexedPolyCurve with arc
//   segments, IfcCompositeCurve of these and of trimmed circles in either sense, arcs read as
//   chords within 1 mm; voids of IfcArbitraryProfileDefWithVoids ignored): the centre line
//   along the 'Axis' (or the footprint's longest side) through the middle of the footprint,
//   the thickness across it, the height the extrusion's depth; an 'Axis' that is a trimmed
//   circle makes an arc wall; the material layer set's thickness is checked against it;
// - half-spaces clipped off a wall (IfcBooleanClippingResult of IfcHalfSpaceSolid,
//   IfcBoxedHalfSpace or IfcPolygonalBoundedHalfSpace): its top (and bottom) over the centre
//   line, as one wall with a sloped top (`height_at_end`) where one plane cuts the whole top,
//   else as walls split where the planes meet or their boundaries end (a gable: two), exact
//   but for a plane sloping across the thickness (read at the centre line; the distance is
//   stated); vertical planes cut ends, which the plan's joins make again;
// - a wall written as an upright profile swept horizontally (an arched or gable end): walls
//   with sloped tops along its top, within 1 cm;
// - IfcCurtainWall: a straight wall over the footprint and height of its IfcMember and
//   IfcPlate parts (IfcRelAggregates), as thick as they are deep (0.1 m if flat), holding its
//   aggregated doors and windows as openings;
// - IfcOpeningElement voiding an imported wall (IfcRelVoidsElement): its body's extent along
//   the wall and in height (a body of faces: its extent), its profile as the opening's `shape`
//   where that lies in the wall's plane and is not a rectangle, a door or a window after the
//   IfcDoor or IfcWindow that fills it (IfcRelFillsElement), with its hinge side from the
//   door's OperationType; one per piece of a wall split under its planes; one voiding a slab
//   is a hole in it where its footprint lies strictly inside the slab and clear of its holes;
// - IfcSlab (and its standard and elemented cases) extruded vertically, with its voids as holes;
// - IfcSite's RefLatitude and RefLongitude as site.location (the longitude's nautical time zone
//   as utc_offset: IFC has none), the model context's TrueNorth as site.north;
// - placements resolved through IfcLocalPlacement chains and mapped items (with their
//   IfcCartesianTransformationOperator); other IfcBooleanResults read as their first operand;
//   the length unit (SI prefixes and conversion-based units such as feet) converted to metres,
//   lengths kept to the micrometre.
// Each object is placed on the level of the storey that contains it
// (IfcRelContainedInSpatialStructure); a model reaching below z = 0 is raised so that its
// lowest point stands at 0 (the plan's floor), and the site is a grid covering it with a margin.
// Everything else is a warning naming the entity ("#1234 IFCROOF 'name': not imported"), and
// so is every approximation (import_approximated, with the distance from the file's geometry
// where it is measured), never a silent drop; `tally` counts them by entity type.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad {

struct IfcImportOptions {
  double site_margin = 1.0;  ///< metres of site around the model
  double cell_size = 1.0;    ///< site tile side, metres
  /// Join tolerance of the plan: BIM tools write coordinates rounded to a tenth of a millimetre
  /// or finer, so centre lines meant to meet do within this.
  double join_tolerance = 1e-4;
};

/// What the import did with the entities of one IFC type.
struct IfcEntityTally {
  std::size_t read = 0;          ///< in the plan, approximated ones included
  std::size_t approximated = 0;  ///< in the plan, but not exactly as the file has them
  std::size_t skipped = 0;       ///< left out, each with a warning
  double distance = 0.0;         ///< metres: the largest measured distance of an approximation
  std::size_t unmeasured = 0;    ///< approximated ones with a distance not measured
  friend bool operator==(const IfcEntityTally&, const IfcEntityTally&) = default;
};

struct IfcImport {
  Plan plan;
  Report warnings;                  ///< every element left out and every approximation
  std::string schema;               ///< FILE_SCHEMA: "IFC4", "IFC2X3", ...
  std::size_t source_walls = 0;     ///< IFC walls and curtain walls in the file
  std::size_t source_openings = 0;  ///< openings voiding an element
  std::size_t source_slabs = 0;
  std::size_t walls_read = 0;  ///< IFC walls and curtain walls in the plan (as one or more walls)
  std::size_t openings_read = 0;  ///< IFC openings in the plan (in walls, or holes in slabs)
  std::size_t slabs_read = 0;
  std::size_t storeys = 0;
  std::size_t skipped = 0;  ///< other products (roofs, stairs, furniture, ...) left out
  double z_shift = 0.0;     ///< metres added to every height of the file
  /// Each plan wall's IFC entity (its instance number): the wall or curtain wall it comes from.
  std::map<std::string, std::uint32_t> wall_sources{};
  /// By IFC entity type ("IFCWALL"): what was read, approximated and skipped.
  std::map<std::string, IfcEntityTally> tally{};
};

/// @return the tally as lines "IFCWALL: 5 read (2 approximated, 0.012 m at most from the file's
///   geometry), 1 skipped", one per type, in order of type name.
[[nodiscard]] std::vector<std::string> format_tally(const IfcImport& import);

/// Imports the text of an IFC file named `file` (in messages).
/// @return the plan (not validated) and its warnings, or a parse_error naming the file and line
///   (not a STEP file, malformed), an `unsupported` error for a schema other than IFC2X3 and
///   IFC4 (IFC4X3 is read as IFC4), or a parse_error for a model with no wall, opening or slab
///   to import. O(n) in the file's size.
[[nodiscard]] Result<IfcImport> import_ifc_text(std::string_view text, std::string_view file,
                                                const IfcImportOptions& options = {});

/// Imports an IFC file. @return as import_ifc_text; an unreadable file is an io_error.
[[nodiscard]] Result<IfcImport> import_ifc_file(const std::filesystem::path& path,
                                                const IfcImportOptions& options = {});

/// @return true if `head` (the first bytes of a file) starts a STEP physical file.
[[nodiscard]] bool is_step_text(std::string_view head);

}  // namespace roomcad
