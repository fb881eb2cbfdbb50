// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/gltf_export.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <unordered_map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/atomic_write.h"
#include "mesh/float_triangulation.h"
#include "plan/plan_objects.h"

namespace roomcad {
namespace {

using Json = nlohmann::json;
using Float3 = std::array<float, 3>;

/// One primitive under construction: its corners (welded by their float32 coordinates) and
/// triangles.
struct Primitive {
  std::vector<Float3> positions;
  std::map<Float3, std::uint32_t> index_of;
  std::vector<std::uint32_t> indices;

  void add(const Float3& p) {
    const auto [it, added] = index_of.emplace(p, static_cast<std::uint32_t>(positions.size()));
    if (added) positions.push_back(p);
    indices.push_back(it->second);
  }
};

/// A node's primitives by colour (0xrrggbb).
using NodeMeshes = std::map<int, std::map<std::uint32_t, Primitive>>;

std::uint32_t colour_key(Color c) {
  return (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
}

/// Adds the mesh's triangles to the nodes of their objects (-1: no object), y up.
void gather(const SolidMesh& mesh, NodeMeshes& nodes) {
  if (mesh.n_faces() == 0) return;
  const FacePropertyHandles h = face_property_handles(mesh);
  for (const FloatTriangle& t : triangulate_in_float(mesh)) {
    Primitive& p =
        nodes[mesh.property(h.object, t.face)][colour_key(mesh.property(h.color, t.face))];
    for (const OpenMesh::Vec3f& c : t.corners) p.add({c[0], c[2], c[1] == 0.0f ? 0.0f : -c[1]});
  }
}

double linear_channel(std::uint32_t value) {
  const double c = value / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// Appends raw little-endian bytes (every supported machine is little-endian, as glTF is).
template <class T>
std::size_t append_bytes(std::string& bin, const std::vector<T>& values) {
  const std::size_t offset = bin.size();
  bin.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  return offset;
}

/// What the extras of an object's node say.
struct ObjectInfo {
  std::string kind;
  std::string level;
};

std::unordered_map<std::string, ObjectInfo> object_infos(const Plan& plan) {
  std::unordered_map<std::string, ObjectInfo> out;
  std::unordered_map<std::string, std::string> wall_level;
  for (const Wall& w : plan.walls)
    wall_level.emplace(w.id, w.level), out.emplace(w.id, ObjectInfo{"wall", w.level});
  for (const Opening& o : plan.openings) {
    const auto it = wall_level.find(o.wall);
    out.emplace(
        o.id, ObjectInfo{std::string(to_string(o.type)), it == wall_level.end() ? "" : it->second});
  }
  for (const Slab& s : plan.slabs) out.emplace(s.id, ObjectInfo{"slab", s.level});
  return out;
}

class GltfBuilder {
 public:
  GltfDocument build(const NodeMeshes& nodes, const Model& model, const Plan& plan,
                     const std::string& bin_uri) {
    const auto infos = object_infos(plan);
    for (const auto& [object, primitives] : nodes) {
      for (const auto& [colour, primitive] : primitives) material(colour);
    }
    Json scene_nodes = Json::array();
    for (const auto& [object, primitives] : nodes) {
      const bool named = object >= 0 && static_cast<std::size_t>(object) < model.objects.size();
      const std::string name = named ? model.objects[static_cast<std::size_t>(object)] : "floor";
      const auto info = infos.find(name);
      Json extras{{"kind", named ? (info != infos.end() ? info->second.kind : "object") : "floor"},
                  {"level", nullptr}};
      if (info != infos.end() && !info->second.level.empty()) extras["level"] = info->second.level;
      Json mesh{{"name", name}, {"primitives", Json::array()}};
      for (const auto& [colour, primitive] : primitives)
        mesh["primitives"].push_back(write(primitive, colour));
      scene_nodes.push_back(json_["nodes"].size());
      json_["nodes"].push_back(
          {{"name", name}, {"mesh", json_["meshes"].size()}, {"extras", extras}});
      json_["meshes"].push_back(mesh);
    }
    json_["asset"] = {{"version", "2.0"}, {"generator", "roomcad"}};
    json_["scene"] = 0;
    json_["scenes"] = Json::array({{{"nodes", scene_nodes}}});
    while (bin_.size() % 4) bin_ += '\0';
    Json buffer{{"byteLength", bin_.size()}};
    if (!bin_uri.empty()) buffer["uri"] = bin_uri;
    if (!bin_.empty()) json_["buffers"] = Json::array({buffer});
    for (const char* list : {"nodes", "meshes", "materials", "accessors", "bufferViews"})
      if (json_[list].empty()) json_.erase(list);
    return {json_.dump(), bin_};
  }

 private:
  Json json_{{"nodes", Json::array()},
             {"meshes", Json::array()},
             {"materials", Json::array()},
             {"accessors", Json::array()},
             {"bufferViews", Json::array()}};
  std::string bin_;
  std::map<std::uint32_t, std::size_t> materials_;

  std::size_t material(std::uint32_t colour) {
    if (const auto it = materials_.find(colour); it != materials_.end()) return it->second;
    const std::size_t index = json_["materials"].size();
    json_["materials"].push_back(
        {{"name", fmt::format("c_{:06x}", colour)},
         {"pbrMetallicRoughness",
          {{"baseColorFactor",
            {linear_channel(colour >> 16), linear_channel((colour >> 8) & 0xff),
             linear_channel(colour & 0xff), 1.0}},
           {"metallicFactor", 0.0},
           {"roughnessFactor", 1.0}}}});
    materials_.emplace(colour, index);
    return index;
  }

  std::size_t view(std::size_t offset, std::size_t length, int target) {
    json_["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}, {"target", target}});
    return json_["bufferViews"].size() - 1;
  }

  Json write(const Primitive& p, std::uint32_t colour) {
    Float3 lo = p.positions.front();
    Float3 hi = lo;
    for (const Float3& q : p.positions) {
      for (std::size_t k = 0; k < 3; ++k)
        lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    }
    const std::size_t positions = append_bytes(bin_, p.positions);
    const std::size_t position_view =
        view(positions, bin_.size() - positions, 34962);  // ARRAY_BUFFER
    const std::size_t indices = append_bytes(bin_, p.indices);
    const std::size_t index_view =
        view(indices, bin_.size() - indices, 34963);  // ELEMENT_ARRAY_BUFFER
    // min and max as the doubles the floats are: a reader compares them with the data exactly.
    json_["accessors"].push_back({{"bufferView", position_view},
                                  {"componentType", 5126},
                                  {"count", p.positions.size()},
                                  {"type", "VEC3"},
                                  {"min", {double{lo[0]}, double{lo[1]}, double{lo[2]}}},
                                  {"max", {double{hi[0]}, double{hi[1]}, double{hi[2]}}}});
    json_["accessors"].push_back({{"bufferView", index_view},
                                  {"componentType", 5125},
                                  {"count", p.indices.size()},
                                  {"type", "SCALAR"}});
    const std::size_t n = json_["accessors"].size();
    return {{"attributes", {{"POSITION", n - 2}}},
            {"indices", n - 1},
            {"material", materials_.at(colour)}};
  }
};

void append_u32(std::string& out, std::uint32_t v) {
  char bytes[4];
  std::memcpy(bytes, &v, 4);
  out.append(bytes, 4);
}

}  // namespace

GltfDocument format_gltf(const Model& model, const Plan& plan, const std::string& bin_uri) {
  NodeMeshes nodes;
  for (const SolidMesh* mesh : {&model.walls, &model.floor, &model.fixtures}) gather(*mesh, nodes);
  // The floor (object -1) comes last, after the objects in table order.
  if (const auto it = nodes.find(-1); it != nodes.end()) {
    auto floor = std::move(it->second);
    nodes.erase(it);
    nodes.emplace(static_cast<int>(model.objects.size()), std::move(floor));
  }
  return GltfBuilder().build(nodes, model, plan, bin_uri);
}

std::string pack_glb(const GltfDocument& document) {
  std::string json = document.json;
  while (json.size() % 4) json += ' ';
  std::string out;
  const std::size_t total =
      12 + 8 + json.size() + (document.bin.empty() ? 0 : 8 + document.bin.size());
  append_u32(out, 0x46546C67);  // "glTF"
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_u32(out, static_cast<std::uint32_t>(json.size()));
  append_u32(out, 0x4E4F534A);  // "JSON"
  out += json;
  if (!document.bin.empty()) {
    append_u32(out, static_cast<std::uint32_t>(document.bin.size()));
    append_u32(out, 0x004E4942);  // "BIN\0"
    out += document.bin;
  }
  return out;
}

Status write_gltf_file(const std::filesystem::path& path, const Model& model, const Plan& plan) {
  const std::string extension = path.extension().string();
  if (extension == ".glb")
    return write_file_atomically(path, pack_glb(format_gltf(model, plan, "")));
  if (extension != ".gltf")
    return Status::failure(Code::unsupported,
                           fmt::format("{}: glTF is written as .glb or .gltf", path.string()));
  std::filesystem::path bin = path;
  bin.replace_extension(".bin");
  const GltfDocument document = format_gltf(model, plan, bin.filename().string());
  if (Status written = write_file_atomically(bin, document.bin); !written) return written;
  return write_file_atomically(path, document.json);
}

}  // namespace roomcad
