// SPDX-License-Identifier: GPL-3.0-or-later
#include "support/solid_tolerance.h"

namespace roomcad::test {

std::map<FaceKind, double> area_by_kind(const SolidMesh& mesh) {
  std::map<FaceKind, double> area;
  const FacePropertyHandles props = face_property_handles(mesh);
  for (const auto f : mesh.faces()) area[mesh.property(props.kind, f)] += face_area(mesh, f);
  return area;
}

}  // namespace roomcad::test
