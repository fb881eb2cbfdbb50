// SPDX-License-Identifier: GPL-3.0-or-later
// Writing a built model as glTF 2.0 (Khronos): `roomcad build PLAN -o model.glb` (binary, one
// file) or `-o model.gltf` (JSON with its buffer in `model.bin` beside it).
//
// - One node per object of the model (walls, openings' fixtures, slabs), named by its id, with
//   `extras: {"kind": "wall"|"door"|"window"|"slab"|..., "level": id or null}`; the floor, which
//   belongs to no object, is one more node named "floor" (kind "floor").
// - One PBR material (metallic 0, roughness 1) per colour, named c_rrggbb, base colour the
//   sRGB colour converted to linear as glTF requires.
// - Each node's mesh has one primitive per material: indexed triangles (unsigned 32-bit
//   indices), float32 positions with their exact min and max; glTF's flat-shading default gives
//   the faces their normals. The triangles are those of the float32 triangulation
//   (triangulate_in_float): no repeated corner and no zero-area triangle after rounding, so the
//   walls' solid keeps its vertex positions to within float32 and stays closed.
// - glTF's y is up: a plan point (x, y, z) is written (x, z, -y).
// The same model gives the same bytes; every file is written atomically.
#pragma once

#include <filesystem>
#include <string>

#include "core/error.h"
#include "mesh/solid_mesh.h"
#include "plan/plan.h"

namespace roomcad {

/// A glTF file's two parts: the JSON document and its binary buffer.
struct GltfDocument {
  std::string json;
  std::string bin;
};

/// @return the glTF of the model, whose buffer is the URI `bin_uri` (empty: the GLB's own
///   buffer). `plan` names each object's kind and level. O(n log n) in the model's faces.
[[nodiscard]] GltfDocument format_gltf(const Model& model, const Plan& plan,
                                       const std::string& bin_uri);

/// @return the GLB (binary glTF) container of a document made with an empty `bin_uri`.
[[nodiscard]] std::string pack_glb(const GltfDocument& document);

/// Writes the model to `path`: `.glb` as one binary file, `.gltf` as JSON plus the buffer in
/// `<stem>.bin` beside it (written first).
/// @return a failure naming the file (I/O) or the extension (neither .glb nor .gltf).
Status write_gltf_file(const std::filesystem::path& path, const Model& model, const Plan& plan);

}  // namespace roomcad
