// SPDX-License-Identifier: GPL-3.0-or-later
// The models the read-back tests write: every bundled example and every imported Sweet Home 3D
// home, built with all parts as `roomcad build --force` builds them (the homes keep the
// validation errors of their sources), and what a written file must hold, taken from the model
// in memory.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "io/mesh_export.h"
#include "io/mesh_read_support.h"
#include "mesh/solid_mesh.h"

namespace roomcad::test {

struct BuiltExample {
  std::string name;            ///< the plan file's stem
  Model model;                 ///< walls, floor and fixtures
  double analytic_volume = 0;  ///< of the wall solid, from the plan alone (cubic metres)
};

/// examples/*.json then examples/sweethome3d/*.json, each built once for the whole test binary.
/// @throws std::runtime_error if a plan does not read.
[[nodiscard]] const std::vector<BuiltExample>& built_examples();

/// @return all three parts of a model, with its object table, as `roomcad build` writes them.
[[nodiscard]] MeshParts all_parts(const Model& model);

/// One face as a file must hold it.
struct ExpectedFace {
  std::vector<std::size_t> corners;  ///< 0-based numbers into the vertices of all parts
  Rgb color;
  std::string group;  ///< the object id, or "floor" for faces of no object
  Point3 normal;
  auto operator<=>(const ExpectedFace&) const = default;
};

/// The vertices and faces of walls, floor and fixtures, in that order.
struct ExpectedMesh {
  std::vector<Point3> vertices;
  std::vector<ExpectedFace> faces;
  std::size_t wall_vertices = 0;  ///< the wall solid's vertices come first
  std::size_t wall_faces = 0;
};
[[nodiscard]] ExpectedMesh expected_mesh(const Model& model);

/// @return the polygons of `read` whose corners are all wall vertices, as points.
[[nodiscard]] std::vector<std::vector<Point3>> wall_polygons(const ReadMesh& read,
                                                             std::size_t wall_vertices);

/// Directed edges not matched by exactly one reverse edge, over polygons given as rings of
/// vertex keys: 0 for a closed, consistently oriented surface where every edge joins two faces.
template <class Key>
[[nodiscard]] std::size_t count_unpaired_edges(const std::vector<std::vector<Key>>& rings) {
  std::map<std::array<Key, 2>, int> uses;
  for (const auto& ring : rings)
    for (std::size_t k = 0; k < ring.size(); ++k) ++uses[{ring[k], ring[(k + 1) % ring.size()]}];
  std::size_t unpaired = 0;
  for (const auto& [edge, count] : uses) {
    const auto reverse = uses.find({edge[1], edge[0]});
    if (count != 1 || reverse == uses.end() || reverse->second != 1) ++unpaired;
  }
  return unpaired;
}

/// The volume the polygons enclose (divergence theorem; each planar polygon fanned from its
/// first corner), in cubic metres. O(n).
[[nodiscard]] double enclosed_volume(const std::vector<std::vector<Point3>>& polygons);

}  // namespace roomcad::test
