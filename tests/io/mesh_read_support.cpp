// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/mesh_read_support.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include <boost/multiprecision/cpp_int.hpp>

namespace roomcad::test {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }

std::vector<std::string_view> lines_of(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.emplace_back(text.data() + start, end - start);
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && line[k] == ' ') ++k;
    const std::size_t start = k;
    while (k < line.size() && line[k] != ' ') ++k;
    if (k > start) words.push_back(line.substr(start, k - start));
  }
  return words;
}

template <class Number>
Number number_of(std::string_view word, const std::string& where) {
  Number x{};
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), x);
  if (error != std::errc() || end != word.data() + word.size())
    fail(where + ": '" + std::string(word) + "' is not a number of the expected type");
  return x;
}

std::string at_line(const char* file, std::size_t n) {
  return std::string(file) + " line " + std::to_string(n + 1);
}

Point3 point_of(const std::vector<std::string_view>& w, std::size_t first,
                const std::string& where) {
  return {number_of<double>(w[first], where), number_of<double>(w[first + 1], where),
          number_of<double>(w[first + 2], where)};
}

std::size_t index_of(long long i, std::size_t count, const std::string& where) {
  if (i < 0 || std::size_t(i) >= count)
    fail(where + ": index " + std::to_string(i) + " out of range");
  return std::size_t(i);
}

int channel_of(std::string_view word, const std::string& where) {
  const int c = number_of<int>(word, where);
  if (c < 0 || c > 255) fail(where + ": colour channel " + std::to_string(c) + " is not 0..255");
  return c;
}

std::map<std::string, Rgb> read_mtl(const std::string& mtl) {
  std::map<std::string, Rgb> materials;
  std::string current;
  const auto lines = lines_of(mtl);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const auto w = words_of(lines[n]);
    const std::string where = at_line("mtl", n);
    if (w.empty() || w[0].front() == '#') continue;
    if (w[0] == "newmtl" && w.size() == 2) {
      current = std::string(w[1]);
      if (!materials.emplace(current, Rgb{-1, -1, -1}).second)
        fail(where + ": material defined twice");
    } else if (w[0] == "Kd" && w.size() == 4 && !current.empty()) {
      for (std::size_t k = 0; k < 3; ++k) {
        const double scaled = number_of<double>(w[k + 1], where) * 255.0;
        const long c = std::lround(scaled);
        if (std::abs(scaled - double(c)) > 1e-9 || c < 0 || c > 255)
          fail(where + ": Kd is not a byte / 255");
        materials[current][k] = int(c);
      }
    } else {
      fail(where + ": unexpected '" + std::string(lines[n]) + "'");
    }
  }
  for (const auto& [name, c] : materials)
    if (c[0] < 0) fail("mtl: material " + name + " has no Kd");
  return materials;
}

// One OBJ face line `f a//n b//n ...`: its 0-based corners, and the normal all corners name.
void read_obj_face(const std::vector<std::string_view>& w, const std::vector<Point3>& normals,
                   ReadMesh& m, const std::string& where) {
  std::vector<std::size_t> corners;
  std::size_t normal = 0;
  for (std::size_t k = 1; k < w.size(); ++k) {
    const std::size_t slashes = w[k].find("//");
    if (slashes == std::string_view::npos)
      fail(where + ": corner '" + std::string(w[k]) + "' is not v//vn");
    corners.push_back(index_of(number_of<long long>(w[k].substr(0, slashes), where) - 1,
                               m.vertices.size(), where));
    const std::size_t n =
        index_of(number_of<long long>(w[k].substr(slashes + 2), where) - 1, normals.size(), where);
    if (k > 1 && n != normal) fail(where + ": the corners of one face name different normals");
    normal = n;
  }
  m.faces.push_back(std::move(corners));
  m.normals.push_back(normals[normal]);
}

}  // namespace

ReadMesh read_obj(const std::string& obj, const std::string& mtl) {
  const std::map<std::string, Rgb> materials = read_mtl(mtl);
  ReadMesh m;
  std::vector<Point3> normals;
  std::string group;
  const Rgb* color = nullptr;
  const auto lines = lines_of(obj);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const auto w = words_of(lines[n]);
    const std::string where = at_line("obj", n);
    if (w.empty() || w[0].front() == '#' || (w[0] == "mtllib" && w.size() == 2)) continue;
    if (w[0] == "v" && w.size() == 4) {
      m.vertices.push_back(point_of(w, 1, where));
    } else if (w[0] == "vn" && w.size() == 4) {
      normals.push_back(point_of(w, 1, where));
    } else if (w[0] == "g" && w.size() == 2) {
      group = std::string(w[1]);
      ++m.group_blocks[group];
    } else if (w[0] == "usemtl" && w.size() == 2) {
      const auto it = materials.find(std::string(w[1]));
      if (it == materials.end())
        fail(where + ": material " + std::string(w[1]) + " is not in the MTL");
      color = &it->second;
    } else if (w[0] == "f" && w.size() >= 4) {
      if (color == nullptr || group.empty()) fail(where + ": a face before any usemtl or g");
      read_obj_face(w, normals, m, where);
      m.colors.push_back(*color);
      m.groups.push_back(group);
    } else {
      fail(where + ": unexpected '" + std::string(lines[n]) + "'");
    }
  }
  return m;
}

ReadMesh read_off(const std::string& text) {
  const auto lines = lines_of(text);
  if (lines.size() < 2 || lines[0] != "OFF") fail("off: no OFF header");
  const auto counts = words_of(lines[1]);
  if (counts.size() != 3) fail("off line 2: not 'vertices faces edges'");
  const auto nv = number_of<std::size_t>(counts[0], "off line 2"),
             nf = number_of<std::size_t>(counts[1], "off line 2");
  if (lines.size() != 2 + nv + nf)
    fail("off: " + std::to_string(lines.size()) + " lines for the counts given");
  ReadMesh m;
  for (std::size_t n = 2; n < 2 + nv; ++n) {
    const auto w = words_of(lines[n]);
    if (w.size() != 3) fail(at_line("off", n) + ": a vertex is not x y z");
    m.vertices.push_back(point_of(w, 0, at_line("off", n)));
  }
  for (std::size_t n = 2 + nv; n < lines.size(); ++n) {
    const std::string where = at_line("off", n);
    const auto w = words_of(lines[n]);
    const std::size_t k = w.empty() ? 0 : number_of<std::size_t>(w[0], where);
    if (k < 3 || w.size() != k + 4) fail(where + ": a face is not 'n v1..vn r g b'");
    std::vector<std::size_t>& face = m.faces.emplace_back();
    for (std::size_t i = 1; i <= k; ++i)
      face.push_back(index_of(number_of<long long>(w[i], where), nv, where));
    m.colors.push_back(
        {channel_of(w[k + 1], where), channel_of(w[k + 2], where), channel_of(w[k + 3], where)});
  }
  return m;
}

namespace {

struct PlyProperty {
  std::string type;  // for a list: the item type
  std::string name;
  bool is_list = false;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

// The header's elements, in order; `body` is set to the first line after end_header.
std::vector<PlyElement> read_ply_header(const std::vector<std::string_view>& lines,
                                        std::size_t& body) {
  if (lines.size() < 2 || lines[0] != "ply" || lines[1] != "format ascii 1.0")
    fail("ply: not ASCII PLY 1.0");
  std::vector<PlyElement> elements;
  for (std::size_t n = 2; n < lines.size(); ++n) {
    const auto w = words_of(lines[n]);
    const std::string where = at_line("ply", n);
    if (!w.empty() && w[0] == "end_header") {
      body = n + 1;
      return elements;
    }
    if (!w.empty() && w[0] == "comment") continue;
    if (w.size() == 3 && w[0] == "element") {
      elements.push_back({std::string(w[1]), number_of<std::size_t>(w[2], where), {}});
    } else if (w.size() == 3 && w[0] == "property" && !elements.empty()) {
      elements.back().properties.push_back({std::string(w[1]), std::string(w[2]), false});
    } else if (w.size() == 5 && w[0] == "property" && w[1] == "list" && w[2] == "uchar" &&
               !elements.empty()) {
      elements.back().properties.push_back({std::string(w[3]), std::string(w[4]), true});
    } else {
      fail(where + ": unexpected '" + std::string(lines[n]) + "'");
    }
  }
  fail("ply: no end_header");
}

// One element line: every property's values by name (a scalar is a list of one).
std::map<std::string, std::vector<double>> read_ply_values(const std::vector<std::string_view>& w,
                                                           const PlyElement& e,
                                                           const std::string& where) {
  std::map<std::string, std::vector<double>> values;
  std::size_t k = 0;
  auto next = [&]() -> std::string_view {
    if (k >= w.size()) fail(where + ": too few values");
    return w[k++];
  };
  for (const PlyProperty& p : e.properties) {
    const std::size_t count =
        p.is_list ? std::size_t(channel_of(next(), where)) : 1;  // list count: uchar
    for (std::size_t i = 0; i < count; ++i) {
      const std::string_view word = next();
      values[p.name].push_back(p.type == "double"  ? number_of<double>(word, where)
                               : p.type == "uchar" ? channel_of(word, where)
                                                   : double(number_of<int>(word, where)));
    }
  }
  if (k != w.size()) fail(where + ": too many values");
  return values;
}

void require_types(const PlyElement& e, const std::map<std::string, std::string>& types) {
  for (const auto& [name, type] : types) {
    bool found = false;
    for (const PlyProperty& p : e.properties) found = found || (p.name == name && p.type == type);
    if (!found) fail("ply: element " + e.name + " has no " + type + " property " + name);
  }
}

}  // namespace

ReadMesh read_ply(const std::string& text) {
  const auto lines = lines_of(text);
  std::size_t n = 0;
  const std::vector<PlyElement> elements = read_ply_header(lines, n);
  if (elements.size() != 2 || elements[0].name != "vertex" || elements[1].name != "face")
    fail("ply: elements are not vertex, face");
  require_types(elements[0], {{"x", "double"}, {"y", "double"}, {"z", "double"}});
  require_types(
      elements[1],
      {{"vertex_indices", "int"}, {"red", "uchar"}, {"green", "uchar"}, {"blue", "uchar"}});
  if (lines.size() != n + elements[0].count + elements[1].count)
    fail("ply: line count does not match the header");
  ReadMesh m;
  for (std::size_t i = 0; i < elements[0].count; ++i, ++n) {
    auto v = read_ply_values(words_of(lines[n]), elements[0], at_line("ply", n));
    m.vertices.push_back({v["x"].at(0), v["y"].at(0), v["z"].at(0)});
  }
  for (std::size_t i = 0; i < elements[1].count; ++i, ++n) {
    const std::string where = at_line("ply", n);
    auto v = read_ply_values(words_of(lines[n]), elements[1], where);
    std::vector<std::size_t>& face = m.faces.emplace_back();
    for (const double x : v["vertex_indices"])
      face.push_back(index_of((long long)x, m.vertices.size(), where));
    if (face.size() < 3) fail(where + ": a face of fewer than 3 corners");
    m.colors.push_back({int(v["red"].at(0)), int(v["green"].at(0)), int(v["blue"].at(0))});
  }
  return m;
}

std::vector<StlFacet> read_stl(const std::string& bytes) {
  if (bytes.size() < 84) fail("stl: shorter than its 84-byte header");
  if (bytes.compare(0, 5, "solid") == 0) fail("stl: a binary header starting with 'solid'");
  auto u32 = [&](std::size_t at) {
    std::uint32_t x = 0;
    for (int k = 3; k >= 0; --k) x = (x << 8) | std::uint8_t(bytes[at + std::size_t(k)]);
    return x;
  };
  const std::uint32_t count = u32(80);
  if (bytes.size() != 84 + 50 * std::size_t(count))
    fail("stl: " + std::to_string(bytes.size()) + " bytes for " + std::to_string(count) +
         " facets");
  std::vector<StlFacet> facets(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = 84 + 50 * i;
    for (std::size_t k = 0; k < 3; ++k) facets[i].normal[k] = std::bit_cast<float>(u32(at + 4 * k));
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t k = 0; k < 3; ++k)
        facets[i].corners[c][k] = std::bit_cast<float>(u32(at + 12 + 12 * c + 4 * k));
  }
  return facets;
}

namespace {

using boost::multiprecision::cpp_int;

// x * 2^149: an integer for every finite float (the smallest subnormal is 2^-149).
cpp_int scaled_to_integer(float x) {
  int e = 0;
  const float m = std::frexp(std::abs(x), &e);       // |x| = m * 2^e, m in [0.5, 1)
  cpp_int r = static_cast<long>(std::ldexp(m, 24));  // exact: a float has 24 significant bits
  const int shift = e - 24 + 149;
  r = shift >= 0 ? cpp_int(r << shift) : cpp_int(r >> -shift);  // a subnormal's low bits are 0
  return x < 0 ? cpp_int(-r) : r;
}

}  // namespace

bool is_flat(const FloatTriangle3& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return true;
  std::array<std::array<cpp_int, 3>, 2> d;
  for (std::size_t k = 0; k < 3; ++k) {
    const cpp_int origin = scaled_to_integer(t[0][k]);
    d[0][k] = scaled_to_integer(t[1][k]) - origin;
    d[1][k] = scaled_to_integer(t[2][k]) - origin;
  }
  for (std::size_t k = 0; k < 3; ++k)  // the cross product, component by component
    if (d[0][(k + 1) % 3] * d[1][(k + 2) % 3] != d[0][(k + 2) % 3] * d[1][(k + 1) % 3])
      return false;
  return true;
}

}  // namespace roomcad::test
