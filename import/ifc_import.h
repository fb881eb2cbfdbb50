// SPDX-License-Identifier: GPL-3.0-or-later
// Importing IFC models (IFC2X3 and IFC4 STEP physical files) as plans:
// `roomcad import model.ifc -o plan.json`.
//
// The common subset of what BIM tools write:
// - IfcBuildingStorey as levels: id its Name, elevation its placement's height, height up to
//   the next storey (the last: up to its highest wall, or 2.8 m);
// - IfcWall, IfcWallStandardCase (and IfcWallElementedCase) whose 'Body' is a vertical
//   extrusion of a rectangle or a closed polyline: the centre line along the 'Axis' (or the
//   footprint's longest side) through the middle of the footprint, the thickness across it,
//   the height the extrusion's depth; the material layer set's thickness is checked against it;
// - IfcOpeningElement voiding an imported wall (IfcRelVoidsElement): its body's extent along
//   the wall and in height, its profile as the opening's `shape` where that lies in the wall's
//   plane and is not a rectangle, a door or a window after the IfcDoor or IfcWindow that fills
//   it (IfcRelFillsElement), with its hinge side from the door's OperationType;
// - IfcSlab (and its standard and elemented cases) extruded vertically from a polyline
//   profile, with its voids as holes;
// - placements resolved through IfcLocalPlacement chains and mapped items; IfcBooleanResult
//   and IfcBooleanClippingResult read as their first operand; the length unit (SI prefixes and
//   conversion-based units such as feet) converted to metres, lengths kept to the micrometre.
// Each object is placed on the level of the storey that contains it
// (IfcRelContainedInSpatialStructure); a model reaching below z = 0 is raised so that its
// lowest point stands at 0 (the plan's floor), and the site is a grid covering it with a margin.
// Everything else is a warning naming the entity ("#1234 IFCCURTAINWALL 'name': not imported"),
// and so is every approximation (import_approximated: a footprint that is not the rectangle of
// its centre line, an opening cut to its wall, a clipped body imported unclipped), never a
// silent drop.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

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

struct IfcImport {
  Plan plan;
  Report warnings;                  ///< every element left out and every approximation
  std::string schema;               ///< FILE_SCHEMA: "IFC4", "IFC2X3", ...
  std::size_t source_walls = 0;     ///< IFC walls in the file
  std::size_t source_openings = 0;  ///< openings voiding an element
  std::size_t source_slabs = 0;
  std::size_t storeys = 0;
  std::size_t skipped = 0;  ///< other products (roofs, stairs, furniture, ...) left out
  double z_shift = 0.0;     ///< metres added to every height of the file
};

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
