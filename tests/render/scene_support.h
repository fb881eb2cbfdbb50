// SPDX-License-Identifier: GPL-3.0-or-later
// Test scenes built as meshes directly, and an exact reference: a ray caster on CGAL's AABB
// tree over the models' own (double precision) polygons.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/solid_mesh.h"
#include "render/camera.h"
#include "render/image.h"

namespace roomcad::test {

inline constexpr Color kWallColor{200, 60, 40};
inline constexpr Color kFloorColor{120, 180, 90};

/// Adds a planar polygon face (counter-clockwise seen from outside) with its properties.
void add_face(SolidMesh& mesh, const std::vector<glm::dvec3>& points, int object, FaceKind kind,
              Color color);

/// Adds the six outward faces of an axis-aligned box.
void add_box(SolidMesh& mesh, const glm::dvec3& min, const glm::dvec3& max, int object,
             Color color = kWallColor);

/// A floor rectangle at z = 0, facing up, as one face (object `object`, kind floor).
void add_floor(SolidMesh& mesh, const glm::dvec2& min, const glm::dvec2& max, int object,
               Color color = kFloorColor);

/// The reference: first hits and occlusion, exact predicates on the model's polygons.
class RayCaster {
 public:
  /// @param[in] meshes the meshes to cast against (triangulated here, in double precision)
  explicit RayCaster(const std::vector<const SolidMesh*>& meshes);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  /// @return rc:object of the first face hit by the ray, or -1 when nothing is hit.
  [[nodiscard]] int first_object(const glm::dvec3& origin, const glm::dvec3& direction) const;
  /// @return whether the open ray from `origin` towards `direction` meets any face.
  [[nodiscard]] bool is_blocked(const glm::dvec3& origin, const glm::dvec3& direction) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

/// A plan camera looking from `eye` at `target` (z up): perspective with a vertical field of
/// view `fov_deg`, or orthographic seeing `view_height` metres when `view_height` > 0.
[[nodiscard]] Camera look_from(const glm::dvec3& eye, const glm::dvec3& target,
                               double fov_deg = 50.0, double view_height = 0.0,
                               const glm::dvec3& up = {0.0, 0.0, 1.0});

/// A camera ray through the centre of pixel (x, y) of a width x height image.
struct PixelRay {
  glm::dvec3 origin;
  glm::dvec3 direction;
};
[[nodiscard]] PixelRay pixel_ray(const CameraMatrices& cam, int width, int height, double x,
                                 double y);

/// @return true when every pixel within `radius` (Chebyshev) of (x, y) has the same value.
[[nodiscard]] bool is_uniform_around(const std::vector<int>& values, int width, int height, int x,
                                     int y, int radius);

/// @return how many depth values are NaN, infinite or negative (0 means nothing drawn there).
[[nodiscard]] int count_bad_depths(const FloatImage& depth);

}  // namespace roomcad::test
