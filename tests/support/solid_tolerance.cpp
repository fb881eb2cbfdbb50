// SPDX-License-Identifier: GPL-3.0-or-later
#include "support/solid_tolerance.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace roomcad::test {

std::map<FaceKind, double> area_by_kind(const SolidMesh& mesh) {
  std::map<FaceKind, double> area;
  const FacePropertyHandles props = face_property_handles(mesh);
  for (const auto f : mesh.faces()) {
    std::vector<OpenMesh::Vec3d> p;
    for (const auto v : mesh.fv_range(f)) p.push_back(mesh.point(v));
    OpenMesh::Vec3d n(0, 0, 0);
    for (std::size_t i = 1; i + 1 < p.size(); ++i) n += OpenMesh::cross(p[i] - p[0], p[i + 1] - p[0]);
    area[mesh.property(props.kind, f)] += n.norm() / 2.0;
  }
  return area;
}

double vertex_rounding(const SolidMesh& mesh) {
  double largest = 0.0;
  for (const auto v : mesh.vertices())
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(mesh.point(v)[k]));
  return std::nextafter(largest, 2 * largest + 1) - largest;
}

double volume_tolerance(const SolidMesh& mesh, double volume) {
  double area = 0.0;
  for (const auto& [kind, a] : area_by_kind(mesh)) area += a;
  return 1e-9 * volume + area * vertex_rounding(mesh);
}

}  // namespace roomcad::test
