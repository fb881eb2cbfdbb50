// SPDX-License-Identifier: GPL-3.0-or-later
// The outside OpenSCAD reference of the modeling benchmark: the plan written as OpenSCAD (the
// union of the wall boxes minus the union of the opening boxes, the same solids as
// nef_reference.h) and run through Debian's `openscad -o out.off`.
#pragma once

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "bench/polygon_measure.h"
#include "plan/plan.h"

namespace roomcad::bench {

inline std::string scad_box(const Wall& w, double u0, double u1, double w0, double w1, double z0,
                            double z1) {
  const double deg = std::atan2(w.to.y - w.from.y, w.to.x - w.from.x) * 180.0 / std::numbers::pi;
  return fmt::format(
      "translate([{},{},0]) rotate([0,0,{}]) translate([{},{},{}]) cube([{},{},{}]);\n", w.from.x,
      w.from.y, deg, u0, w0, z0, u1 - u0, w1 - w0, z1 - z0);
}

/// @return the plan as OpenSCAD source: walls extended by half their thickness at both ends,
///         openings a centimetre wider than their wall on each side (no coincident faces).
inline std::string to_scad(const Plan& plan) {
  std::string out = "difference() {\nunion() {\n";
  for (const Wall& w : plan.walls) {
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y), t = w.thickness / 2;
    out += scad_box(w, -t, length + t, -t, t, w.base, w.base + w.height);
  }
  out += "}\nunion() {\n";
  for (const Opening& o : plan.openings) {
    const Wall& w = *find_wall(plan, o.wall);
    const double t = w.thickness / 2 + 0.01;
    out += scad_box(w, o.offset, o.offset + o.width, -t, t, w.base + o.sill,
                    w.base + o.sill + o.height);
  }
  return out + "}\n}\n";
}

/// Reads an OFF file (as OpenSCAD writes it). @return nothing if it cannot be read. O(n).
inline std::optional<PolygonSoup> read_off(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 0;
  if (!(in >> magic >> nv >> nf >> ne) || magic != "OFF") return std::nullopt;
  PolygonSoup soup;
  soup.points.resize(nv);
  for (auto& p : soup.points)
    if (!(in >> p[0] >> p[1] >> p[2])) return std::nullopt;
  soup.polygons.resize(nf);
  for (auto& f : soup.polygons) {
    std::size_t n = 0;
    if (!(in >> n)) return std::nullopt;
    f.resize(n);
    for (auto& i : f)
      if (!(in >> i) || i >= nv) return std::nullopt;
    in.ignore(1 << 20, '\n');  // optional face colour
  }
  return soup;
}

/// Runs `openscad -o OUT.off` on the plan in `dir`. @return its result, or nothing if
/// openscad is missing or fails (or runs past `timeout_s` seconds).
inline std::optional<PolygonSoup> run_openscad(const Plan& plan, const std::filesystem::path& dir,
                                               int timeout_s) {
  const auto scad = dir / "grid.scad", off = dir / "grid.off";
  std::ofstream(scad) << to_scad(plan);
  std::filesystem::remove(off);
  const std::string command = fmt::format("timeout {} openscad -o '{}' '{}' >/dev/null 2>&1",
                                          timeout_s, off.string(), scad.string());
  if (std::system(command.c_str()) != 0) return std::nullopt;
  return read_off(off);
}

}  // namespace roomcad::bench
