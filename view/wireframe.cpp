// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/wireframe.h"

#include <array>
#include <optional>

#include "render/line_raster.h"

namespace roomcad {
namespace {

constexpr Rgb kWireColor{0x18, 0x28, 0x60};

/// The pixel a point projects to, or nullopt when it is behind the near plane.
std::optional<ScreenPoint> project(const glm::dmat4& view_projection, const glm::vec3& p, int width,
                                   int height) {
  const glm::dvec4 clip = view_projection * glm::dvec4(glm::dvec3(p), 1.0);
  if (!(clip.w > 1e-9)) return std::nullopt;
  const double x = clip.x / clip.w, y = clip.y / clip.w;
  // Reversed-Z: depth above 1 is nearer than the near plane.
  if (!(clip.z / clip.w <= 1.0)) return std::nullopt;
  return ScreenPoint{(x + 1.0) * 0.5 * width - 0.5, (1.0 - y) * 0.5 * height - 0.5};
}

}  // namespace

void draw_wireframe(RgbImage& image, const Scene& scene, const CameraMatrices& camera) {
  const glm::dmat4 view_projection = rebase_camera(camera, scene.origin).view_projection;
  for (std::size_t t = 0; t < scene.triangle_count(); ++t) {
    std::array<std::optional<ScreenPoint>, 3> p;
    for (int i = 0; i < 3; ++i)
      p[i] = project(view_projection, scene.corners[3 * t + i], image.width, image.height);
    for (int i = 0; i < 3; ++i) {
      const auto& a = p[i];
      const auto& b = p[(i + 1) % 3];
      if (a && b) draw_line(image, *a, *b, kWireColor);
    }
  }
}

}  // namespace roomcad
