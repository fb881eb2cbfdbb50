// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/mesh_export.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <map>

#include "io/atomic_write.h"
#include "mesh/float_triangulation.h"

namespace roomcad {
namespace {

void append_coordinate(std::string& out, double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x + 0.0).ptr;  // -0 -> 0
  out.append(buffer, end);
}

void append_int(std::string& out, long long x) {
  char buffer[24];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  out.append(buffer, end);
}

void append_point(std::string& out, const OpenMesh::Vec3d& p) {
  append_coordinate(out, p[0]);
  out += ' ';
  append_coordinate(out, p[1]);
  out += ' ';
  append_coordinate(out, p[2]);
}

// STL stores float32, little endian.
void append_float(std::string& out, float x) {
  const auto bits = std::bit_cast<std::uint32_t>(x);
  for (int k = 0; k < 4; ++k) out += static_cast<char>((bits >> (8 * k)) & 0xffu);
}

void append_float3(std::string& out, const OpenMesh::Vec3f& p) {
  for (int k = 0; k < 3; ++k) append_float(out, p[k]);
}

std::string material_name(Color c) { return "c_" + to_string(c).substr(1); }

/// Calls visit(mesh, face, first vertex number of the mesh) for every face of every part.
template <class Visit>
void for_each_face(const MeshParts& parts, Visit&& visit) {
  std::size_t base = 0;
  for (const SolidMesh* mesh : parts.meshes) {
    for (const auto f : mesh->faces()) visit(*mesh, f, base);
    base += mesh->n_vertices();
  }
}

std::size_t count_vertices(const MeshParts& parts) {
  std::size_t n = 0;
  for (const SolidMesh* mesh : parts.meshes) n += mesh->n_vertices();
  return n;
}

std::size_t count_faces(const MeshParts& parts) {
  std::size_t n = 0;
  for (const SolidMesh* mesh : parts.meshes) n += mesh->n_faces();
  return n;
}

void append_vertices(std::string& out, const MeshParts& parts, const char* prefix) {
  for (const SolidMesh* mesh : parts.meshes)
    for (const auto v : mesh->vertices()) {
      out += prefix;
      append_point(out, mesh->point(v));
      out += '\n';
    }
}

// One line per face: the corner count, the 0-based vertex numbers, then red green blue.
void append_colored_faces(std::string& out, const MeshParts& parts) {
  for_each_face(parts, [&](const SolidMesh& mesh, SolidMesh::FaceHandle f, std::size_t base) {
    append_int(out, static_cast<long long>(mesh.valence(f)));
    for (const auto v : mesh.fv_range(f)) {
      out += ' ';
      append_int(out, static_cast<long long>(base + std::size_t(v.idx())));
    }
    const Color c = mesh.property(face_property_handles(mesh).color, f);
    out += ' ' + std::to_string(c.r) + ' ' + std::to_string(c.g) + ' ' + std::to_string(c.b) + '\n';
  });
}

// An OBJ group name is one word: white space in an id becomes '_'.
std::string group_name(const MeshParts& parts, int object) {
  if (object < 0 || parts.objects == nullptr || std::size_t(object) >= parts.objects->size())
    return "floor";
  std::string name = (*parts.objects)[std::size_t(object)];
  std::replace_if(
      name.begin(), name.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
  return name.empty() ? "_" : name;
}

struct FaceRef {
  const SolidMesh* mesh;
  SolidMesh::FaceHandle face;
  std::size_t base;
  std::size_t normal;  // 1-based OBJ normal number
};

void append_obj_face(std::string& out, const FaceRef& r) {
  out += 'f';
  for (const auto v : r.mesh->fv_range(r.face)) {
    out += ' ';
    append_int(out, static_cast<long long>(r.base + std::size_t(v.idx()) + 1));
    out += "//";
    append_int(out, static_cast<long long>(r.normal));
  }
  out += '\n';
}

// Groups the faces by object (objects in table order, faces of no object last), keeping each
// group's faces in mesh order.
std::map<int, std::vector<FaceRef>> faces_by_object(const MeshParts& parts) {
  std::map<int, std::vector<FaceRef>> groups;
  std::size_t normal = 0;
  for_each_face(parts, [&](const SolidMesh& mesh, SolidMesh::FaceHandle f, std::size_t base) {
    const int object = mesh.property(face_property_handles(mesh).object, f);
    groups[object < 0 ? INT32_MAX : object].push_back({&mesh, f, base, ++normal});
  });
  return groups;
}

}  // namespace

Result<MeshFormat> mesh_format_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".off") return MeshFormat::off;
  if (ext == ".ply") return MeshFormat::ply;
  if (ext == ".stl") return MeshFormat::stl;
  return Result<MeshFormat>::failure(Code::unsupported,
                                     "output file '" + path.string() + "': extension '" + ext +
                                         "' is not one of .obj, .off, .ply, .stl");
}

std::string format_obj(const MeshParts& parts, const std::string& mtl_name) {
  std::string out = "# roomcad model\nmtllib " + mtl_name + "\n";
  append_vertices(out, parts, "v ");
  for_each_face(parts, [&](const SolidMesh& mesh, SolidMesh::FaceHandle f, std::size_t) {
    out += "vn ";
    append_point(out, mesh.normal(f));
    out += '\n';
  });
  for (const auto& [object, faces] : faces_by_object(parts)) {
    out += "g " + group_name(parts, object == INT32_MAX ? -1 : object) + "\n";
    std::string material;
    for (const FaceRef& r : faces) {
      const std::string m =
          material_name(r.mesh->property(face_property_handles(*r.mesh).color, r.face));
      if (m != material) out += "usemtl " + (material = m) + "\n";
      append_obj_face(out, r);
    }
  }
  return out;
}

std::string format_mtl(const MeshParts& parts) {
  std::map<std::string, Color> colors;
  for_each_face(parts, [&](const SolidMesh& mesh, SolidMesh::FaceHandle f, std::size_t) {
    const Color c = mesh.property(face_property_handles(mesh).color, f);
    colors.emplace(material_name(c), c);
  });
  std::string out = "# roomcad materials\n";
  for (const auto& [name, c] : colors) {
    out += "newmtl " + name + "\nKd ";
    append_point(out, OpenMesh::Vec3d(c.r / 255.0, c.g / 255.0, c.b / 255.0));
    out += "\n";
  }
  return out;
}

std::string format_off(const MeshParts& parts) {
  std::string out = "OFF\n";
  append_int(out, static_cast<long long>(count_vertices(parts)));
  out += ' ';
  append_int(out, static_cast<long long>(count_faces(parts)));
  out += " 0\n";
  append_vertices(out, parts, "");
  append_colored_faces(out, parts);
  return out;
}

std::string format_ply(const MeshParts& parts) {
  std::string out = "ply\nformat ascii 1.0\ncomment roomcad model\nelement vertex ";
  append_int(out, static_cast<long long>(count_vertices(parts)));
  out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  append_int(out, static_cast<long long>(count_faces(parts)));
  out +=
      "\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nend_header\n";
  append_vertices(out, parts, "");
  append_colored_faces(out, parts);
  return out;
}

std::string format_stl(const MeshParts& parts) {
  std::string body;
  std::uint32_t count = 0;
  for (const SolidMesh* mesh : parts.meshes)
    for (const FloatTriangle& t : triangulate_in_float(*mesh)) {
      append_float3(body, OpenMesh::Vec3f(mesh->normal(t.face)));
      for (const auto& corner : t.corners) append_float3(body, corner);
      body += std::string(2, '\0');
      ++count;
    }
  std::string out(80, ' ');
  const std::string title = "roomcad model (binary STL, float32, little endian)";
  out.replace(0, title.size(), title);
  for (int k = 0; k < 4; ++k) out += static_cast<char>((count >> (8 * k)) & 0xffu);
  return out + body;
}

Status write_mesh_file(const std::filesystem::path& path, const MeshParts& parts) {
  const Result<MeshFormat> format = mesh_format_of(path);
  if (!format) return format.status();
  switch (format.value()) {
    case MeshFormat::obj: {
      std::filesystem::path mtl = path;
      mtl.replace_extension(".mtl");
      if (Status s = write_file_atomically(mtl, format_mtl(parts)); !s) return s;
      return write_file_atomically(path, format_obj(parts, mtl.filename().string()));
    }
    case MeshFormat::off: return write_file_atomically(path, format_off(parts));
    case MeshFormat::ply: return write_file_atomically(path, format_ply(parts));
    case MeshFormat::stl: return write_file_atomically(path, format_stl(parts));
  }
  return Status::failure(Code::internal, "output file '" + path.string() + "': unknown format");
}

}  // namespace roomcad
