// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/assembly/face_soup.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>

#include <fmt/format.h>

#include "core/assert.h"
#include "core/flat_index.h"
#include "solid/build_model.h"

namespace roomcad::detail {
namespace {

using PointKey = std::array<std::uint64_t, 4>;  // a point's coordinates' bits, and its copy
constexpr std::uint32_t kNoVertex = UINT32_MAX;

// Adding 0.0 turns -0.0 into +0.0, so that the two zeros share a vertex.
PointKey key_of(const OpenMesh::Vec3d& p, std::uint32_t copy) {
  return {std::bit_cast<std::uint64_t>(p[0] + 0.0), std::bit_cast<std::uint64_t>(p[1] + 0.0),
          std::bit_cast<std::uint64_t>(p[2] + 0.0), copy};
}

std::string object_name(const std::vector<std::string>& objects, int object) {
  if (object < 0 || static_cast<std::size_t>(object) >= objects.size()) return "(none)";
  return objects[static_cast<std::size_t>(object)];
}

struct Corners {
  std::vector<std::size_t> vertex, next;  // per corner, in polygon order
  std::vector<std::size_t> parent;        // union-find over corners
  std::size_t find(std::size_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  }
};

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
      return fmt::format(
          "an edge shared by more than two faces: a face of '{}' is already "
          "on that side (complex edge)",
          name_face(mesh.face_handle(side)));
  }
  return std::nullopt;
}

// A polygon soup's corners as split_fans numbers them (polygons in order).
struct SoupCorners {
  const std::vector<std::vector<std::size_t>>& polygons;
  const std::vector<OpenMesh::Vec3d>& points;
  const std::vector<std::size_t>& first_corner;  // per polygon, and the end
  const FlatIndex<std::uint64_t>& corner_after;  // edge a->b (key a * points + b): a corner at b
};

// One face's use of an edge that more than two faces share.
struct EdgeSide {
  std::uint32_t start = 0, end = 0;  // its corners at the edge's ends, in the face's order
  double angle = 0.0;                // of the face about the edge
  bool forward = false;              // runs from the edge's lower point index to the higher
};

// Where more than two faces meet at an edge (solids touching along it: walls meeting at a
// corner only, a slab's corner on a wall's edge), pairs each face with the one across the
// solid's material from it. Sorted by angle about b - a (right-handed), the faces alternate in
// direction, and a face running a -> b bounds the wedge of material between it and the face
// before it: turning from such a face towards larger angles turns towards its normal, out of
// the material. The angles are of the rounded faces, in floating point: only which neighbour,
// never a coordinate, comes of them.
// @param[out] across  per corner at an end of a paired face, the corner it joins in its pair
// @param[out] sides   every face's (start, end) corners at the shared edges
// @return false (bad_edge set) where the faces do not alternate. O(k log k) per edge of k faces.
bool pair_faces_at_shared_edges(const SoupCorners& soup, const std::vector<std::uint32_t>& repeats,
                                std::unordered_map<std::size_t, std::size_t>& across,
                                std::vector<std::pair<std::uint32_t, std::uint32_t>>& sides,
                                std::pair<std::size_t, std::size_t>& bad_edge) {
  const std::size_t n_points = soup.points.size();
  const auto polygon_of = [&](std::size_t corner) {
    return std::size_t(
        std::upper_bound(soup.first_corner.begin(), soup.first_corner.end(), corner) -
        soup.first_corner.begin() - 1);
  };
  const auto point_at = [&](std::size_t corner) {
    const std::size_t p = polygon_of(corner);
    return soup.polygons[p][corner - soup.first_corner[p]];
  };
  const auto previous = [&](std::size_t corner) {
    const std::size_t p = polygon_of(corner);
    return corner == soup.first_corner[p] ? soup.first_corner[p + 1] - 1 : corner - 1;
  };
  // Each shared edge once (lower point first), with the corners after it each way.
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::uint32_t>> ends;
  for (const std::uint32_t r : repeats) {
    const std::size_t a = point_at(previous(r)), b = point_at(r);
    std::vector<std::uint32_t>& list = ends[{std::min(a, b), std::max(a, b)}];
    if (list.empty())
      for (const std::uint64_t key :
           {std::uint64_t(a) * n_points + b, std::uint64_t(b) * n_points + a})
        if (const std::uint32_t first = soup.corner_after.find(key);
            first != FlatIndex<std::uint64_t>::kNone)
          list.push_back(first);
    list.push_back(r);
  }
  std::vector<OpenMesh::Vec3d> face;
  for (const auto& [edge, after] : ends) {
    const auto [a, b] = edge;
    const OpenMesh::Vec3d d = soup.points[b] - soup.points[a];
    // Two directions across the edge: from d and the axis it is least along.
    int axis = 0;
    for (int k = 1; k < 3; ++k) axis = std::abs(d[k]) < std::abs(d[axis]) ? k : axis;
    OpenMesh::Vec3d along_axis(0.0, 0.0, 0.0);
    along_axis[axis] = 1.0;
    const OpenMesh::Vec3d e1 = OpenMesh::cross(d, along_axis), e2 = OpenMesh::cross(d, e1);
    std::vector<EdgeSide> around;
    for (const std::uint32_t end : after) {
      const std::size_t p = polygon_of(end);
      face.clear();
      for (const std::size_t i : soup.polygons[p]) face.push_back(soup.points[i]);
      const bool forward = point_at(end) == b;
      const OpenMesh::Vec3d into = OpenMesh::cross(polygon_normal(face), forward ? d : -d);
      around.push_back({std::uint32_t(previous(end)), end,
                        std::atan2(OpenMesh::dot(into, e2), OpenMesh::dot(into, e1)), forward});
    }
    std::sort(around.begin(), around.end(), [](const EdgeSide& x, const EdgeSide& y) {
      return std::tie(x.angle, x.start) < std::tie(y.angle, y.start);
    });
    const std::size_t k = around.size();
    for (std::size_t i = 0; i < k; ++i)
      if (around[i].forward == around[(i + 1) % k].forward) {
        bad_edge = {a, b};
        return false;
      }
    for (std::size_t i = 0; i < k; ++i) {
      sides.emplace_back(around[i].start, around[i].end);
      if (!around[i].forward) continue;
      const EdgeSide& f = around[i];
      const EdgeSide& g = around[(i + k - 1) % k];
      const bool once = across.emplace(f.start, g.end).second &&  // at a
                        across.emplace(g.start, f.end).second;    // at b
      RC_ASSERT(once, "a face's corner at a shared edge pairs with one face only");
    }
  }
  return true;
}

}  // namespace

FanSplit split_fans(const std::vector<std::vector<std::size_t>>& polygons,
                    const std::vector<OpenMesh::Vec3d>& points,
                    std::pair<std::size_t, std::size_t>& bad_edge) {
  const std::size_t n_points = points.size();
  Corners c;
  std::vector<std::size_t> first_corner{0};
  for (const auto& poly : polygons) first_corner.push_back(first_corner.back() + poly.size());
  const std::size_t corners = first_corner.back();
  c.vertex.reserve(corners), c.next.reserve(corners), c.parent.reserve(corners);
  FlatIndex<std::uint64_t> corner_after(corners);  // edge a->b: the corner at b
  std::vector<std::uint32_t> repeats;              // corners after an edge already taken
  for (const auto& poly : polygons)
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const std::size_t prev = poly[(k + poly.size() - 1) % poly.size()];
      const std::size_t id = c.vertex.size();
      c.vertex.push_back(poly[k]);
      c.next.push_back(poly[(k + 1) % poly.size()]);
      c.parent.push_back(id);
      if (!corner_after.try_emplace(std::uint64_t(prev) * n_points + poly[k], std::uint32_t(id))
               .second)
        repeats.push_back(std::uint32_t(id));
    }
  std::unordered_map<std::size_t, std::size_t> across_shared;  // on an edge of more than two faces
  std::vector<std::pair<std::uint32_t, std::uint32_t>> shared_sides;
  if (!repeats.empty() &&
      !pair_faces_at_shared_edges({polygons, points, first_corner, corner_after}, repeats,
                                  across_shared, shared_sides, bad_edge))
    return {};
  // A corner joins the corner of the neighbouring face across its outgoing edge.
  for (std::size_t id = 0; id < c.vertex.size(); ++id) {
    std::uint32_t across = corner_after.find(std::uint64_t(c.next[id]) * n_points + c.vertex[id]);
    if (!across_shared.empty())
      if (const auto it = across_shared.find(id); it != across_shared.end())
        across = std::uint32_t(it->second);
    if (across != FlatIndex<std::uint64_t>::kNone) c.parent[c.find(id)] = c.find(across);
  }
  // Each fan (a root) is one vertex: the next copy of its point.
  std::vector<std::uint32_t> vertex_of_root(c.vertex.size(), UINT32_MAX), copies_used(n_points, 0),
      copy_of_vertex;
  FanSplit out;
  out.copy.resize(c.vertex.size()), out.vertex.resize(c.vertex.size());
  for (std::size_t id = 0; id < c.vertex.size(); ++id) {
    std::uint32_t& vertex = vertex_of_root[c.find(id)];
    if (vertex == UINT32_MAX) {
      vertex = std::uint32_t(copy_of_vertex.size());
      copy_of_vertex.push_back(copies_used[c.vertex[id]]++);
    }
    out.copy[id] = copy_of_vertex[vertex];
    out.vertex[id] = vertex;
  }
  // Faces paired at a shared edge must end on separate copies of it, or the mesh could not
  // hold them (their fans join elsewhere: the surface is no manifold there).
  std::set<std::pair<std::uint32_t, std::uint32_t>> shared_edges;
  for (const auto& [start, end] : shared_sides)
    if (!shared_edges.emplace(out.vertex[start], out.vertex[end]).second) {
      bad_edge = {c.vertex[start], c.vertex[end]};
      return {};
    }
  out.first_corner = std::move(first_corner);
  return out;
}

void set_corners(SoupFace& face, const std::vector<std::vector<std::size_t>>& polygons,
                 std::size_t k, const std::vector<OpenMesh::Vec3d>& points, const FanSplit& fans) {
  face.points.reserve(polygons[k].size());
  for (const std::size_t i : polygons[k]) face.points.push_back(points[i]);
  const auto corners = std::ptrdiff_t(fans.first_corner[k]),
             end = std::ptrdiff_t(fans.first_corner[k + 1]);
  // Copy 0 everywhere (nearly every face) is said by no copies at all.
  if (std::any_of(fans.copy.begin() + corners, fans.copy.begin() + end,
                  [](std::uint32_t c) { return c != 0; }))
    face.copies.assign(fans.copy.begin() + corners, fans.copy.begin() + end);
  face.vertices.assign(fans.vertex.begin() + corners, fans.vertex.begin() + end);
}

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
  const auto corners_of = [](const FaceSoup& soup) {
    std::size_t n = 0;
    for (const SoupFace& f : soup) n += f.points.size();
    return n;
  };
  std::size_t faces = 0, corners = 0;
  for (const FaceSoup& soup : soups) faces += soup.size(), corners += corners_of(soup);
  // Each corner is shared by about three faces; reserving avoids rehashing and regrowing.
  mesh.reserve(corners / 3 + 1, corners / 2 + faces, faces);
  // Unshared soups start a table each, sized for that soup (the 70 x 70 grid's fixtures, in
  // one table sized for all, spent 13% of their build clearing it).
  FlatIndex<PointKey> vertices(share ? corners / 3 + 1 : 0);
  std::vector<SolidMesh::VertexHandle> face;
  const ObjectNamer name_face = [&](SolidMesh::FaceHandle fh) {
    return object_name(objects, mesh.property(props.object, fh));
  };
  // The mesh vertex of each of the soup's vertex numbers (SoupFace::vertices) found so far.
  std::vector<std::uint32_t> vertex_of_number;
  for (const FaceSoup& soup : soups) {
    if (!share) vertices = FlatIndex<PointKey>(corners_of(soup) / 3 + 1);
    vertex_of_number.clear();
    for (const SoupFace& f : soup) {
      face.clear();
      for (std::size_t k = 0; k < f.points.size(); ++k) {
        std::uint32_t* known = nullptr;
        if (!f.vertices.empty()) {
          if (f.vertices[k] >= vertex_of_number.size())
            vertex_of_number.resize(f.vertices[k] + 1, kNoVertex);
          known = &vertex_of_number[f.vertices[k]];
          if (*known != kNoVertex) {
            face.push_back(SolidMesh::VertexHandle(int(*known)));
            continue;
          }
        }
        const OpenMesh::Vec3d& p = f.points[k];
        const auto next = std::uint32_t(mesh.n_vertices());
        const auto [vertex, added] =
            vertices.try_emplace(key_of(p, f.copies.empty() ? 0 : f.copies[k]), next);
        if (added) mesh.add_vertex(p);
        if (known) *known = vertex;
        face.push_back(SolidMesh::VertexHandle(int(vertex)));
      }
      std::optional<std::string> problem = find_add_face_problem(mesh, face, name_face);
      const SolidMesh::FaceHandle fh = problem ? SolidMesh::FaceHandle() : mesh.add_face(face);
      if (!fh.is_valid()) {
        const OpenMesh::Vec3d at = f.points.empty() ? OpenMesh::Vec3d(0, 0, 0) : f.points[0];
        throw PreconditionError(
            fmt::format(
                "build_model: a {} face of '{}' with {} corners near ({}, {}, {}) would make the "
                "mesh non-manifold: {}",
                to_string(f.kind), object_name(objects, f.object), f.points.size(), at[0], at[1],
                at[2], problem.value_or("OpenMesh refused it")),
            Code::not_buildable);
      }
      mesh.property(props.object, fh) = f.object;
      mesh.property(props.kind, fh) = f.kind;
      mesh.property(props.color, fh) = f.color;
      mesh.set_normal(fh, polygon_normal(f.points).normalized());
    }
  }
  return mesh;
}

void require_closed(const SolidMesh& mesh, const std::vector<std::string>& objects) {
  const FacePropertyHandles props = face_property_handles(mesh);
  std::set<std::string> beside;
  std::size_t open = 0;
  SolidMesh::HalfedgeHandle first;
  for (const auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h)) continue;
    if (open++ == 0) first = h;
    beside.insert(object_name(
        objects, mesh.property(props.object, mesh.face_handle(mesh.opposite_halfedge_handle(h)))));
  }
  if (open == 0) return;
  const OpenMesh::Vec3d a = mesh.point(mesh.from_vertex_handle(first)),
                        b = mesh.point(mesh.to_vertex_handle(first));
  throw PreconditionError(
      fmt::format(
          "build_model: the solid is not closed beside the faces of '{}': {} edges have a face "
          "on one side only, the first from ({}, {}, {}) to ({}, {}, {}) (features finer than the "
          "rounding of "
          "their corners to doubles, such as a wall an ulp long where walls overlap)",
          fmt::join(beside, "', '"), open, a[0], a[1], a[2], b[0], b[1], b[2]),
      Code::not_buildable);
}

}  // namespace roomcad::detail
