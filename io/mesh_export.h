// SPDX-License-Identifier: GPL-3.0-or-later
// Writing built models as mesh files: OBJ (+ MTL), OFF, PLY and STL, chosen by extension.
//
// Coordinates are written as the shortest decimal that reads back to the same double
// (std::to_chars), except in STL, whose format stores float32 (each coordinate rounded to the
// nearest float, mesh/float_triangulation.h). Output bytes depend only on the meshes: the
// same model gives the same file.
// Every file goes through write_file_atomically: a failed export leaves no partial file.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "mesh/solid_mesh.h"

namespace roomcad {

enum class MeshFormat { obj, off, ply, stl };

/// @return the format named by the path's extension (.obj .off .ply .stl, any case), or a
///         failure naming the path and the supported extensions.
[[nodiscard]] Result<MeshFormat> mesh_format_of(const std::filesystem::path& path);

/// The meshes to write, as one file: every part's faces, with the shared object table.
struct MeshParts {
  std::vector<const SolidMesh*> meshes;  ///< each with rc: face properties and face normals
  const std::vector<std::string>* objects = nullptr;  ///< ids that rc:object indexes
};

/// OBJ text: `mtllib <mtl_name>`, vertices, one `vn` per face, one group `g <object id>` per
/// object (faces of no object: group `floor`), `usemtl c_rrggbb` per colour. O(n log n).
[[nodiscard]] std::string format_obj(const MeshParts& parts, const std::string& mtl_name);
/// MTL text: one material `c_rrggbb` per colour used, diffuse colour Kd. O(n log n).
[[nodiscard]] std::string format_mtl(const MeshParts& parts);
/// OFF text: polygon faces, each followed by its colour as three integers 0..255. O(n).
[[nodiscard]] std::string format_off(const MeshParts& parts);
/// PLY text (format ascii 1.0): double vertices, polygon faces with uchar red/green/blue. O(n).
[[nodiscard]] std::string format_ply(const MeshParts& parts);
/// Binary STL: float32 normals (each face's own) and corners, little endian. Each part is
/// triangulated on its corners rounded to float32 (triangulate_in_float), so no facet has a
/// repeated corner or zero area and a closed part stays closed when a reader welds corners by
/// their coordinates. O(n log n) for faces of bounded size.
[[nodiscard]] std::string format_stl(const MeshParts& parts);

/// Writes the parts to `path` in the format of its extension; for OBJ also writes the MTL
/// beside it (same stem, `.mtl`), before the OBJ.
/// @return a failure naming the file and the reason (bad extension, I/O).
Status write_mesh_file(const std::filesystem::path& path, const MeshParts& parts);

}  // namespace roomcad
