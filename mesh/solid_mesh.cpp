// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/solid_mesh.h"

#include "core/assert.h"

namespace roomcad {

std::string_view to_string(FaceKind k) {
  switch (k) {
    case FaceKind::wall_face: return "wall_face";
    case FaceKind::wall_top: return "wall_top";
    case FaceKind::wall_bottom: return "wall_bottom";
    case FaceKind::wall_end: return "wall_end";
    case FaceKind::jamb: return "jamb";
    case FaceKind::sill: return "sill";
    case FaceKind::lintel: return "lintel";
    case FaceKind::floor: return "floor";
    case FaceKind::door: return "door";
    case FaceKind::window: return "window";
    case FaceKind::slab: return "slab";
  }
  return "unknown";
}

void add_face_properties(SolidMesh& mesh) {
  // get_property_handle finds a property added earlier, which makes this idempotent.
  OpenMesh::FPropHandleT<int> object;
  if (!mesh.get_property_handle(object, kObjectProperty))
    mesh.add_property(object, kObjectProperty);
  OpenMesh::FPropHandleT<FaceKind> kind;
  if (!mesh.get_property_handle(kind, kKindProperty)) mesh.add_property(kind, kKindProperty);
  OpenMesh::FPropHandleT<Color> color;
  if (!mesh.get_property_handle(color, kColorProperty)) mesh.add_property(color, kColorProperty);
  mesh.request_face_normals();
}

FacePropertyHandles face_property_handles(const SolidMesh& mesh) {
  FacePropertyHandles h;
  const bool labelled = mesh.get_property_handle(h.object, kObjectProperty) &&
                        mesh.get_property_handle(h.kind, kKindProperty) &&
                        mesh.get_property_handle(h.color, kColorProperty);
  RC_ASSERT(labelled, "add_face_properties gave the mesh its rc: face properties");
  return h;
}

double face_area(const SolidMesh& mesh, SolidMesh::FaceHandle face) {
  OpenMesh::Vec3d n(0, 0, 0), first(0, 0, 0), last(0, 0, 0);
  bool started = false;
  for (const auto v : mesh.fv_range(face)) {
    const OpenMesh::Vec3d& p = mesh.point(v);
    if (started) n += OpenMesh::cross(last - first, p - first);
    else first = p, started = true;
    last = p;
  }
  return n.norm() / 2.0;
}

}  // namespace roomcad
