#include "modeling/detail/face_soup.h"

#include <bit>
#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>

#include <fmt/format.h>

#include "modeling/build_model.h"

namespace roomcad::detail {
namespace {

struct PointKey {
  std::uint64_t x, y, z;
  friend bool operator==(const PointKey&, const PointKey&) = default;
};

struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
    h ^= k.y + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= k.z + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

// Adding 0.0 turns -0.0 into +0.0, so that the two zeros share a vertex.
PointKey key_of(const OpenMesh::Vec3d& p) {
  return {std::bit_cast<std::uint64_t>(p[0] + 0.0), std::bit_cast<std::uint64_t>(p[1] + 0.0),
          std::bit_cast<std::uint64_t>(p[2] + 0.0)};
}

std::string object_name(const std::vector<std::string>& objects, int object) {
  if (object < 0 || static_cast<std::size_t>(object) >= objects.size()) return "(none)";
  return objects[static_cast<std::size_t>(object)];
}

using ObjectNamer = std::function<std::string(SolidMesh::FaceHandle)>;

// Why OpenMesh would refuse to add a face with these corners (a repeated corner makes it
// abort on an assertion, "complex edge"/"complex vertex" only print), checked before add_face
// so that a bad soup is an error naming the walls, not a crash; nullopt when the face can be
// added. A corner with a free gap has exactly one, so OpenMesh never needs another to relink
// a fan there. O(n^2 + sum of corner valences) for n corners.
std::optional<std::string> find_add_face_problem(const SolidMesh& mesh,
                                                 std::span<const SolidMesh::VertexHandle> face,
                                                 const ObjectNamer& name_face) {
  const std::size_t n = face.size();
  if (n < 3) return fmt::format("it has {} corners, fewer than 3", n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (face[i] == face[j]) return "it repeats a corner";
  for (std::size_t i = 0; i < n; ++i) {
    if (!mesh.is_boundary(face[i])) return "a corner is closed all round (complex vertex)";
    const SolidMesh::HalfedgeHandle side = mesh.find_halfedge(face[i], face[(i + 1) % n]);
    if (side.is_valid() && !mesh.is_boundary(side))
      return fmt::format("an edge shared by more than two faces: a face of '{}' is already "
                         "on that side (complex edge)",
                         name_face(mesh.face_handle(side)));
  }
  return std::nullopt;
}

}  // namespace

OpenMesh::Vec3d polygon_normal(std::span<const OpenMesh::Vec3d> points) {
  OpenMesh::Vec3d n(0.0, 0.0, 0.0);
  if (points.empty()) return n;
  // Relative to the first point: exact differences for nearby doubles, far from the origin too.
  const OpenMesh::Vec3d o = points[0];
  for (std::size_t i = 1; i + 1 < points.size(); ++i)
    n += OpenMesh::cross(points[i] - o, points[i + 1] - o);
  return n;
}

SolidMesh assemble_mesh(std::span<const FaceSoup> soups, const std::vector<std::string>& objects,
                        bool share) {
  SolidMesh mesh;
  add_face_properties(mesh);
  const FacePropertyHandles props = face_property_handles(mesh);
  std::unordered_map<PointKey, SolidMesh::VertexHandle, PointKeyHash> vertices;
  std::vector<SolidMesh::VertexHandle> face;
  const ObjectNamer name_face = [&](SolidMesh::FaceHandle fh) {
    return object_name(objects, mesh.property(props.object, fh));
  };
  for (const FaceSoup& soup : soups) {
    if (!share) vertices.clear();
    for (const SoupFace& f : soup) {
      face.clear();
      for (const OpenMesh::Vec3d& p : f.points) {
        auto [it, added] = vertices.try_emplace(key_of(p));
        if (added) it->second = mesh.add_vertex(p);
        face.push_back(it->second);
      }
      std::optional<std::string> problem = find_add_face_problem(mesh, face, name_face);
      const SolidMesh::FaceHandle fh = problem ? SolidMesh::FaceHandle() : mesh.add_face(face);
      if (!fh.is_valid()) {
        const OpenMesh::Vec3d at = f.points.empty() ? OpenMesh::Vec3d(0, 0, 0) : f.points[0];
        throw PreconditionError(fmt::format(
            "build_model: a {} face of '{}' with {} corners near ({}, {}, {}) would make the "
            "mesh non-manifold: {}",
            to_string(f.kind), object_name(objects, f.object), f.points.size(), at[0], at[1],
            at[2], problem.value_or("OpenMesh refused it")));
      }
      mesh.property(props.object, fh) = f.object;
      mesh.property(props.kind, fh) = f.kind;
      mesh.property(props.color, fh) = f.color;
      mesh.set_normal(fh, polygon_normal(f.points).normalized());
    }
  }
  return mesh;
}

}  // namespace roomcad::detail
