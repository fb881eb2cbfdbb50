// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzer bytes as a small plan (for fuzz_build and fuzz_render): a few walls and openings
// drawn from tables that favour what breaks geometry code: ends shared with earlier walls
// (mitres, T and X joins, bow-ties of short walls between sharp ones), walls repeated or
// nested, zero-length and hairline walls, hairline thicknesses and heights, openings flush
// with every end, the base and the top, and coordinates tiny, huge or far from the origin,
// some nudged by an ulp. The plan is not validated: it is built as `--force` builds it.
// A byte past the end reads as 0, so every input is a plan.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "plan/plan.h"

namespace roomcad::fuzz {

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  template <class T, std::size_t N>
  const T& pick(const std::array<T, N>& table) {
    return table[next() % N];
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

inline constexpr std::array<double, 6> kScales{1.0, 1e-3, 10.0, 1e-7, 1e5, 0.25};
inline constexpr std::array<double, 5> kShifts{0.0, 1e3, -7.5e5, 3.3e7, 0.1};
inline constexpr std::array<double, 7> kThickness{0.2, 0.1, 0.25, 0.5, 1e-9, 2.0, 0.075};
inline constexpr std::array<double, 5> kHeight{2.5, 1.0, 3.0, 1e-9, 0.5};
inline constexpr std::array<double, 5> kBase{0.0, 1.0, 2.5, -0.5, 1e-9};
inline constexpr std::array<double, 6> kSpan{0.9, 1.0, 0.5, 0.0, 1e-9, 1.5};  // of an opening

inline double nudge(double v, std::uint8_t how) {
  switch (how % 4) {
    case 1: return std::nextafter(v, INFINITY);
    case 2: return std::nextafter(v, -INFINITY);
    default: return v;
  }
}

// "w3" and the like (built with += since GCC 12 warns, wrongly, on char* + std::string).
inline std::string named(char prefix, int i) {
  std::string id(1, prefix);
  id += std::to_string(i);
  return id;
}

/// @return a plan of 1 to 6 walls and 0 to 3 openings decoded from the bytes.
inline Plan decode_plan(const std::uint8_t* data, std::size_t size) {
  ByteReader r(data, size);
  Plan plan;
  const double scale = r.pick(kScales), shift = r.pick(kShifts);
  auto grid = [&] {
    return shift + (int(r.next() % 9) - 4) * scale + (r.next() % 4) * 0.3 * scale;
  };
  std::vector<Point2> points;
  auto some_point = [&]() -> Point2 {
    const std::uint8_t how = r.next();
    if (how % 3 == 0 && !points.empty()) return points[r.next() % points.size()];
    return {nudge(grid(), how / 3), nudge(grid(), how / 12)};
  };
  const int walls = 1 + r.next() % 6;
  for (int i = 0; i < walls; ++i) {
    Wall w;
    w.id = named('w', i);
    w.from = some_point();
    switch (r.next() % 5) {
      case 0: w.to = w.from; break;  // zero length
      case 1:
        w.to = {nudge(w.from.x, 1), w.from.y + 1e-9 * scale * (r.next() % 3)};
        break;  // hairline
      default: w.to = some_point(); break;
    }
    w.thickness = r.pick(kThickness) * scale;
    w.height = r.pick(kHeight) * scale;
    w.base = r.pick(kBase) * scale;
    points.push_back(w.from), points.push_back(w.to);
    plan.walls.push_back(std::move(w));
  }
  const int openings = r.next() % 4;
  for (int i = 0; i < openings; ++i) {
    const Wall& w = plan.walls[r.next() % plan.walls.size()];
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
    Opening o;
    o.id = named('o', i);
    o.wall = w.id;
    o.type = r.next() % 2 ? OpeningType::door : OpeningType::window;
    o.width = std::min(r.pick(kSpan) * scale, length);
    o.height = std::min(r.pick(kSpan) * 2.0 * scale, w.height);
    const std::uint8_t where = r.next();
    o.offset = where % 3 == 0   ? 0.0
               : where % 3 == 1 ? length - o.width
                                : (length - o.width) / 2.0;  // flush or middle
    o.sill = where / 3 % 3 == 0   ? 0.0
             : where / 3 % 3 == 1 ? w.height - o.height
                                  : (w.height - o.height) / 2.0;
    plan.openings.push_back(std::move(o));
  }
  return plan;
}

/// @return a committed corpus file (fuzz/corpus/<target>/) decoded as its target decodes it,
/// so that the tests build every seed the fuzzers start from.
inline Plan decode_plan_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  return decode_plan(bytes.data(), bytes.size());
}

/// @return the files of a corpus folder, sorted by name.
inline std::vector<std::filesystem::path> corpus_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace roomcad::fuzz
