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

// Why OpenMesh would refuse (or, for a vertex with no free gap, abort on an assertion) to add
// a face with these corners, checked before add_face so that a bad soup is an error, not a
// crash; nullopt when the face can be added. O(n + sum of corner valences).
std::optional<std::string> find_add_face_problem(const SolidMesh& mesh,
                                                 std::span<const SolidMesh::VertexHandle> face,
                                                 const ObjectNamer& name_face) {
  const std::size_t n = face.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (face[i] == face[j]) return "it repeats a corner";
  std::vector<SolidMesh::HalfedgeHandle> sides(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!mesh.is_boundary(face[i])) return "a corner is closed all round (complex vertex)";
    sides[i] = mesh.find_halfedge(face[i], face[(i + 1) % n]);
    if (sides[i].is_valid() && !mesh.is_boundary(sides[i]))
      return fmt::format("an edge shared by more than two faces: a face of '{}' is already "
                         "on that side (complex edge)",
                         name_face(mesh.face_handle(sides[i])));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const SolidMesh::HalfedgeHandle in = sides[i], out = sides[(i + 1) % n];
    if (!in.is_valid() || !out.is_valid() || mesh.next_halfedge_handle(in) == out) continue;
    // Both sides exist but are not consecutive: OpenMesh moves the fan between them into
    // another free gap at that corner, and there must be one besides `in`.
    int gaps = 0;
    for (SolidMesh::ConstVertexIHalfedgeIter h = mesh.cvih_iter(face[(i + 1) % n]); h.is_valid(); ++h)
      gaps += mesh.is_boundary(*h) ? 1 : 0;
    if (gaps < 2) return "two cones would meet at a corner with no free gap (complex vertex)";
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
      if (const auto problem = find_add_face_problem(mesh, face, name_face))
        throw PreconditionError(fmt::format(
            "build_model: a {} face of '{}' with {} corners near ({}, {}, {}) would make the "
            "mesh non-manifold: {}",
            to_string(f.kind), object_name(objects, f.object), f.points.size(), f.points[0][0],
            f.points[0][1], f.points[0][2], *problem));
      const SolidMesh::FaceHandle fh = mesh.add_face(face);
      mesh.property(props.object, fh) = f.object;
      mesh.property(props.kind, fh) = f.kind;
      mesh.property(props.color, fh) = f.color;
      mesh.set_normal(fh, polygon_normal(f.points).normalized());
    }
  }
  return mesh;
}

}  // namespace roomcad::detail
