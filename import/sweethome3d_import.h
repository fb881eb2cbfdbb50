// SPDX-License-Identifier: GPL-3.0-or-later
// Importing Sweet Home 3D homes (`Home.xml`, or a `.sh3d` archive holding one) as plans.
//
// Mapping (centimetres to metres, Sweet Home 3D's downward y negated; plan format version 2
// when the home uses levels, slopes, arcs, shapes or rooms):
// - each `<level>` becomes a level (its name as id where unique), at its elevation;
// - each `<wall>` becomes a wall of its level, with `height_at_end` for a sloped top and
//   `arc_extent` for a curved one; on every level but the lowest it reaches down through the
//   level's floor (base = -floorThickness), as in Sweet Home 3D, so storeys stack with no gap;
// - wall ends that Sweet Home 3D draws anywhere inside the wall they meet are moved onto its
//   centre line or end (sh3d::join_t_ends), so that the plan's join rule sees the junction;
// - each `<doorOrWindow>` becomes an opening of the wall that holds it (found by geometry: see
//   sh3d::place_openings), width along the wall, sill from its elevation, its cut-out shape
//   as its `shape`, and of every other wall it passes through (`<id>-2`, ...);
// - each `<room>` becomes a floor slab on the levels above the lowest, and (`ceilings`) a
//   ceiling slab where no floor above covers it (sh3d::make_slabs);
// - z values and opening edges lie on a 2^-20 m grid, so that `base + height`, `offset + width`
//   and `sill + height` are exact: what touches in the home touches exactly in the plan;
// - the whole home is raised so that its lowest level stands at z = 0 (a basement below ground
//   in Sweet Home 3D starts at 0 in the plan);
// - the site is a grid of `cell_size` tiles covering the walls plus `site_margin`;
// - one default sun, and the home's observer and aerial cameras.
// What cannot be represented is a warning that names the wall or item concerned.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"
#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad {

struct Sh3dImportOptions {
  std::optional<std::string> level{};  ///< import only the level with this name; all if unset
  /// The plan's `site.chord_tolerance` (metres between an arc and its chords; also the one
  /// for curved cut-out shapes); unset: the format's default (1 mm), not written.
  std::optional<double> chord_tolerance{};
  /// Also import rooms' ceilings as slabs where no floor above covers them (sh3d::make_slabs).
  /// Off by default: Sweet Home 3D draws a ceiling as a surface seen from below only, so a
  /// home seen from above shows its rooms; as slabs they would close every top storey.
  bool ceilings = false;
  double site_margin = 1.0;  ///< metres of site around the walls
  double cell_size = 1.0;    ///< site tile side, metres
  /// Join tolerance of the plan. Sweet Home 3D keeps float32 centimetres (a few 1e-7 m of
  /// rounding at 10 m), so an end point drawn onto another wall's centre line can miss it by
  /// about 1e-6 m; 1e-5 m absorbs that and is far below any drawn detail.
  double join_tolerance = 1e-5;
};

struct Sh3dImport {
  Plan plan;
  Report warnings;               ///< every approximation or omission, naming the object
  std::size_t source_walls = 0;  ///< `<wall>` elements imported (before splitting arcs)
  std::size_t source_items = 0;  ///< `<doorOrWindow>` elements on the imported levels
  double z_shift = 0.0;          ///< metres added to every Sweet Home 3D elevation
};

/// Most (wall, door-or-window or level) pairs an import matches: the work is proportional.
inline constexpr double kMaxImportPairs = 1e9;
/// Most site cells along a side of an imported home (a billion metres at the default size).
inline constexpr double kMaxSiteCellsPerSide = 1e9;

/// Imports the text of a `Home.xml`. `file` names the source in messages.
/// @return the plan and its warnings, or an error naming the file, element, attribute and
///   value (malformed XML, a missing or non-numeric attribute, an unknown `--level` name, a
///   home with no walls to import, more than kMaxImportPairs pairs of walls and items or
///   levels, walls spread over more than kMaxSiteCellsPerSide cells, more walls (arcs counted
///   by their chords) or doors and windows than a plan may hold, 1,000,000 of each). The plan
///   is not validated. O(walls x items).
[[nodiscard]] Result<Sh3dImport> import_sweethome3d_text(std::string_view xml,
                                                         std::string_view file,
                                                         const Sh3dImportOptions& options = {});

/// Imports a `Home.xml` file, or a `.sh3d` archive (recognised by its content, whatever its
/// name) through its `Home.xml` entry.
/// @return as import_sweethome3d_text; unreadable files and archives without `Home.xml` are
///   errors naming the file.
[[nodiscard]] Result<Sh3dImport> import_sweethome3d_file(const std::filesystem::path& path,
                                                         const Sh3dImportOptions& options = {});

}  // namespace roomcad
