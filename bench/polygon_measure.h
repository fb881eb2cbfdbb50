// SPDX-License-Identifier: GPL-3.0-or-later
// Size and volume of a polygon soup (any closed, outward surface), measured the same way for
// every path of the modeling benchmark: triangles as each n-gon's n - 2, volume by the
// divergence theorem over a fan of each planar polygon.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace roomcad::bench {

struct PolygonSoup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
};

/// @return the number of triangles of the soup once each n-gon is cut into n - 2. O(n).
inline std::size_t count_triangles(const PolygonSoup& soup) {
  std::size_t n = 0;
  for (const auto& p : soup.polygons) n += p.size() >= 3 ? p.size() - 2 : 0;
  return n;
}

/// @return the enclosed volume (m^3, positive for outward faces). O(n) in corners.
inline double measure_volume(const PolygonSoup& soup) {
  double six_v = 0.0;
  for (const auto& p : soup.polygons)
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      const auto& a = soup.points[p[0]];
      const auto& b = soup.points[p[k]];
      const auto& c = soup.points[p[k + 1]];
      six_v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
  return six_v / 6.0;
}

}  // namespace roomcad::bench
