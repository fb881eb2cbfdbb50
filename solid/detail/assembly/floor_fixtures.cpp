// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/assembly/floor_fixtures.h"

#include <cmath>

#include <fmt/format.h>

#include "solid/build_model.h"

namespace roomcad::detail {
namespace {

constexpr Color kDoorColor{0x8b, 0x5a, 0x2b};
constexpr Color kWindowColor{0xa8, 0xd0, 0xe6};
constexpr double kDoorThickness = 0.04;
constexpr double kPaneThickness = 0.02;

Color darker(Color c) {
  auto scale = [](std::uint8_t v) { return static_cast<std::uint8_t>(v * 9 / 10); };
  return {scale(c.r), scale(c.g), scale(c.b)};
}

// A closed box over a counter-clockwise quad, from z0 to z1; nothing for a box the doubles
// cannot hold (corners that round together: a hairline opening's pane or leaf).
void add_box(const std::array<Point2, 4>& quad, double z0, double z1, SoupFace proto,
             FaceSoup& out) {
  if (!(z0 < z1)) return;
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t m = k + 1; m < 4; ++m)
      if (quad[k] == quad[m]) return;
  auto p = [&](std::size_t k, double z) { return OpenMesh::Vec3d(quad[k].x, quad[k].y, z); };
  proto.points = {p(3, z0), p(2, z0), p(1, z0), p(0, z0)};
  out.push_back(proto);
  proto.points = {p(0, z1), p(1, z1), p(2, z1), p(3, z1)};
  out.push_back(proto);
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t n = (k + 1) % 4;
    proto.points = {p(k, z0), p(n, z0), p(n, z1), p(k, z1)};
    out.push_back(proto);
  }
}

Point2 at(const WallFrame& f, double u, double w) {
  return {f.from.x + f.dir.x * u + f.normal.x * w, f.from.y + f.dir.y * u + f.normal.y * w};
}

// The quad spanned by u in [u0, u1] and w in [w0, w1] of a wall's frame, counter-clockwise.
std::array<Point2, 4> frame_quad(const WallFrame& f, double u0, double u1, double w0, double w1) {
  return {at(f, u0, w0), at(f, u1, w0), at(f, u1, w1), at(f, u0, w1)};
}

std::array<Point2, 4> door_quad(const WallFrame& f, const Hole& h, const Opening& o) {
  const double side = o.swing == Swing::in ? 1.0 : -1.0;
  const double w0 = side * f.half, w1 = side * (f.half + (h.u1 - h.u0));
  const double u0 = o.hinge == Hinge::left ? h.u0 : h.u1 - kDoorThickness;
  const double u1 = u0 + kDoorThickness;
  return side > 0 ? frame_quad(f, u0, u1, w0, w1) : frame_quad(f, u0, u1, w1, w0);
}

}  // namespace

FaceSoup build_floor(const Site& site) {
  const auto nx = site.cells[0], ny = site.cells[1];
  const double s = site.cell_size;
  if (nx <= 0 || ny <= 0 || !(s > 0.0) || !std::isfinite(s) || nx * ny > 10'000'000)
    throw PreconditionError(fmt::format("build_model: the site's floor cannot be built: cells "
                                        "[{}, {}], cell_size {} (need 1 to 10^7 tiles of a "
                                        "positive finite size)",
                                        nx, ny, s),
                            Code::not_buildable);
  FaceSoup soup;
  soup.reserve(static_cast<std::size_t>(nx * ny));
  auto corner = [&](std::int64_t i, std::int64_t j) {
    return OpenMesh::Vec3d(site.origin.x + double(i) * s, site.origin.y + double(j) * s, 0.0);
  };
  const Color dark = darker(site.floor_color);
  for (std::int64_t j = 0; j < ny; ++j)
    for (std::int64_t i = 0; i < nx; ++i)
      soup.push_back({{corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)},
                      FaceKind::floor,
                      -1,
                      (i + j) % 2 == 0 ? site.floor_color : dark,
                      {},
                      {}});
  return soup;
}

std::vector<FaceSoup> build_fixtures(const Plan& plan, std::span<const WallFrame> frames) {
  std::vector<FaceSoup> soups;
  for (const WallFrame& f : frames)
    for (const Hole& h : f.holes) {
      const Opening& o = plan.openings[h.opening];
      const int object = opening_object(plan, h.opening);
      FaceSoup& soup = soups.emplace_back();
      if (o.type == OpeningType::window) {
        const double w = std::min(kPaneThickness, f.half) / 2.0;
        add_box(frame_quad(f, h.u0, h.u1, -w, w), h.z0, h.z1,
                {{}, FaceKind::window, object, kWindowColor, {}, {}}, soup);
      } else {
        add_box(door_quad(f, h, o), h.z0, h.z1, {{}, FaceKind::door, object, kDoorColor, {}, {}},
                soup);
      }
    }
  return soups;
}

}  // namespace roomcad::detail
