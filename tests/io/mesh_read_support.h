// SPDX-License-Identifier: GPL-3.0-or-later
// Small readers of the mesh files roomcad writes (OBJ + MTL, OFF, ASCII PLY, binary STL), for
// the read-back tests. They share no code with io/mesh_export: each follows its format's own
// description, reads numbers with std::from_chars (exact), and throws std::runtime_error naming
// the line or the facet on anything it does not expect.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace roomcad::test {

using Point3 = std::array<double, 3>;
using Rgb = std::array<int, 3>;  ///< 0..255 each

/// A polygon mesh as read back from a file.
struct ReadMesh {
  std::vector<Point3> vertices;
  std::vector<std::vector<std::size_t>> faces;  ///< 0-based vertex numbers, in file order
  std::vector<Rgb> colors;                      ///< per face
  std::vector<std::string> groups;              ///< per face: its OBJ group (OBJ only)
  std::vector<Point3> normals;                  ///< per face: the `vn` its corners name (OBJ only)
  std::map<std::string, int> group_blocks;      ///< OBJ: how many `g` lines name each group
};

/// Reads OBJ text (`v`, `vn`, `g`, `usemtl`, `f v//vn ...`; every corner of a face names the same
/// normal) with the MTL text it names (`newmtl`, `Kd` = colour / 255, exact to 1e-9).
[[nodiscard]] ReadMesh read_obj(const std::string& obj, const std::string& mtl);
/// Reads OFF text whose faces end with their colour as three integers.
[[nodiscard]] ReadMesh read_off(const std::string& text);
/// Reads ASCII PLY text by its header: vertex x y z as double; face vertex_indices and uchar
/// red green blue.
[[nodiscard]] ReadMesh read_ply(const std::string& text);

using FloatPoint = std::array<float, 3>;
using FloatTriangle3 = std::array<FloatPoint, 3>;

struct StlFacet {
  FloatPoint normal;
  FloatTriangle3 corners;
};
/// Reads a binary STL: an 80-byte header that does not start with "solid" (which would make
/// readers take it for ASCII), a little-endian facet count, and exactly that many 50-byte facets.
[[nodiscard]] std::vector<StlFacet> read_stl(const std::string& bytes);

/// True if two corners are equal or all three lie on one line, decided exactly (integers).
[[nodiscard]] bool is_flat(const FloatTriangle3& corners);

}  // namespace roomcad::test
