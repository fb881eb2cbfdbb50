// SPDX-License-Identifier: GPL-3.0-or-later
// The ground and obstructions of an outdoor picture, and the obstructions' outlines.
#include "render/outdoors.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mesh/triangulate_face.h"
#include "render/line_raster.h"

namespace roomcad {
namespace {

/// The world corners of an obstruction's prism: its outline at `base` and at the top.
struct Prism {
  std::vector<glm::dvec3> bottom, top;
};

Prism prism_of(const Obstruction& o) {
  Prism p;
  for (const Point2& v : o.outline) {
    p.bottom.emplace_back(v.x, v.y, o.base);
    p.top.emplace_back(v.x, v.y, o.base + o.height);
  }
  return p;
}

/// The sides (outward for a counter-clockwise outline) and the top of a prism, as triangles.
std::vector<glm::dvec3> prism_triangles(const Prism& p) {
  std::vector<glm::dvec3> out;
  const std::size_t n = p.bottom.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    out.insert(out.end(), {p.bottom[i], p.bottom[j], p.top[j], p.bottom[i], p.top[j], p.top[i]});
  }
  std::vector<OpenMesh::Vec3d> points;
  for (const glm::dvec3& v : p.top) points.emplace_back(v.x, v.y, v.z);
  for (const auto& t : triangulate_face(points, OpenMesh::Vec3d(0, 0, 1)))
    for (const int k : t) out.push_back(p.top[static_cast<std::size_t>(k)]);
  return out;
}

/// The ground: a square under the box, kGroundMargin of its largest side beyond it.
std::vector<glm::dvec3> ground_triangles(const Box3& box) {
  const double size =
      std::max({box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2], 1.0});
  const double margin = kGroundMargin * size, z = box.low[2] - 0.01;
  const glm::dvec3 a(box.low[0] - margin, box.low[1] - margin, z);
  const glm::dvec3 b(box.high[0] + margin, box.low[1] - margin, z);
  const glm::dvec3 c(box.high[0] + margin, box.high[1] + margin, z);
  const glm::dvec3 d(box.low[0] - margin, box.high[1] + margin, z);
  return {a, b, c, a, c, d};
}

/// One point of an edge as the camera sees it: its pixel and its distance along the view.
struct Seen {
  glm::dvec2 pixel;
  double distance;
};

Seen see(const CameraMatrices& cam, const glm::dvec3& p, int width, int height) {
  const glm::dvec4 clip = cam.view_projection * glm::dvec4(p, 1.0);
  return {{(clip.x / clip.w + 1.0) * 0.5 * width, (1.0 - clip.y / clip.w) * 0.5 * height},
          glm::dot(p - cam.eye, cam.forward)};
}

void outline_edge(const CameraMatrices& cam, glm::dvec3 a, glm::dvec3 b, const FloatImage& depth,
                  Rgb color, RgbImage& image) {
  if (!cam.orthographic) {  // keep the part in front of the near plane
    const double da = glm::dot(a - cam.eye, cam.forward), db = glm::dot(b - cam.eye, cam.forward);
    if (da < kPerspectiveNear && db < kPerspectiveNear) return;
    const auto cut = [&](double from, double to) {
      return (kPerspectiveNear - from) / (to - from);
    };
    if (da < kPerspectiveNear) a += (b - a) * cut(da, db);
    if (db < kPerspectiveNear) b += (a - b) * cut(db, da);
  }
  const Seen sa = see(cam, a, image.width, image.height),
             sb = see(cam, b, image.width, image.height);
  const double length =
      std::max(std::abs(sb.pixel.x - sa.pixel.x), std::abs(sb.pixel.y - sa.pixel.y));
  // two points a pixel (perspective spaces them unevenly), at most a few times across the image
  const int steps =
      static_cast<int>(std::min(2.0 * length, 4.0 * (image.width + image.height))) + 1;
  for (int s = 0; s <= steps; ++s) {
    const Seen q =
        see(cam, a + (b - a) * (static_cast<double>(s) / steps), image.width, image.height);
    const int x = static_cast<int>(std::floor(q.pixel.x)),
              y = static_cast<int>(std::floor(q.pixel.y));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
    const float nearest = depth.at(x, y);
    if (nearest > 0.f && q.distance > nearest * 1.002 + 0.02) continue;  // behind a surface
    std::copy(color.begin(), color.end(), image.at(x, y));
  }
}

}  // namespace

Outdoors night_outdoors(std::vector<Obstruction> obstructions) {
  return Outdoors{.obstructions = std::move(obstructions),
                  .sky_top = {0x14, 0x1c, 0x30},
                  .sky_horizon = {0x4a, 0x55, 0x70},
                  .ground = {0x6e, 0x74, 0x60},
                  .outline = {0xe0, 0xe0, 0xe0}};
}

Light sun_and_sky_light(const Vec3& to_sun) {
  if (to_sun.z > 0)
    return Light{.id = "sun", .direction = {-to_sun.x, -to_sun.y, -to_sun.z}, .ambient = 0.35};
  return Light{.id = "sky", .direction = {0, 0, -1}, .intensity = 0.6, .ambient = 1.0};
}

void add_outdoors(const Outdoors& outdoors, Scene& scene) {
  Box3 around = model_bounds(scene);
  std::vector<Prism> prisms;
  for (const Obstruction& o : outdoors.obstructions) {
    prisms.push_back(prism_of(o));
    for (const glm::dvec3& v : prisms.back().bottom) add_point(around, v);
    for (const glm::dvec3& v : prisms.back().top) add_point(around, v);
  }
  if (is_empty(around)) add_point(around, glm::dvec3(0.0));
  append_triangles(ground_triangles(around), outdoors.ground, FaceKind::slab, kColourPass, scene);
  for (const Prism& p : prisms)
    append_triangles(prism_triangles(p), outdoors.ground, FaceKind::wall_face, kShadowPass, scene);
}

void outline_obstructions(const Outdoors& outdoors, const CameraMatrices& camera,
                          const FloatImage& depth, RgbImage& color) {
  const Rgb ink{outdoors.outline.r, outdoors.outline.g, outdoors.outline.b};
  for (const Obstruction& o : outdoors.obstructions) {
    const Prism p = prism_of(o);
    const std::size_t n = p.bottom.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      outline_edge(camera, p.bottom[i], p.bottom[j], depth, ink, color);
      outline_edge(camera, p.top[i], p.top[j], depth, ink, color);
      outline_edge(camera, p.bottom[i], p.top[i], depth, ink, color);
    }
  }
}

}  // namespace roomcad
