// SPDX-License-Identifier: GPL-3.0-or-later
// Cameras: from a plan camera, from flags, from a view preset, or the default framing, and the
// view/projection matrices the pipeline uses (right-handed, z up in the world, reversed-Z).
#pragma once

#include <optional>
#include <string_view>

#include <glm/glm.hpp>

#include "core/box.h"
#include "plan/plan.h"

namespace roomcad {

/// The corners of a box (core/box.h) as the renderer's vectors.
[[nodiscard]] inline glm::dvec3 low_corner(const Box3& b) { return {b.low[0], b.low[1], b.low[2]}; }
[[nodiscard]] inline glm::dvec3 high_corner(const Box3& b) {
  return {b.high[0], b.high[1], b.high[2]};
}
/// Grows `b` to hold `p`. O(1).
inline void add_point(Box3& b, const glm::dvec3& p) { add_point(b, p.x, p.y, p.z); }

/// The six fixed views and the south-west perspective one (`--view`).
enum class ViewPreset { front, back, left, right, top, iso };
/// @return the preset named `text` (front|back|left|right|top|iso), or nullopt.
[[nodiscard]] std::optional<ViewPreset> parse_view_preset(std::string_view text);

/// The near plane distance of perspective cameras, metres. With reversed-Z float depth the
/// precision does not depend on it much, so it can be small enough to walk through doors.
inline constexpr double kPerspectiveNear = 0.05;

/// The matrices of one camera (cameras themselves are the plan's Camera: eye, target, up, fov,
/// view height, all in world metres).
struct CameraMatrices {
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  glm::dmat4 view_projection{1.0};
  glm::dvec3 eye{0.0};
  glm::dvec3 forward{0.0, 1.0, 0.0};  ///< unit view direction
  bool orthographic = false;
};

/// Builds the view and a reversed-Z projection: perspective has an infinite far plane and
/// depth = near / distance; orthographic maps the scene's depth range (with a margin) to
/// [1, 0]. A degenerate up (parallel to the view) is replaced by world y. O(1).
/// @param[in] camera  eye != target (else the view looks north from the eye)
/// @param[in] scene   the model's bounds: the orthographic depth range is fitted to them
/// @param[in] aspect  width / height of the image, > 0
[[nodiscard]] CameraMatrices make_camera_matrices(const Camera& camera, const Box3& scene,
                                                  double aspect);

/// The same camera for points given relative to `origin` (a scene's frame, scene.h): the view
/// is moved by `origin` in double, before the pipeline turns it into float, so that float
/// positions near the scene stay precise however far the scene is from (0, 0, 0). O(1).
/// @return matrices taking (point - origin); eye relative to origin; forward and projection
///         unchanged
[[nodiscard]] CameraMatrices rebase_camera(const CameraMatrices& camera, const glm::dvec3& origin);

/// Frames `scene` from a preset direction: the whole box is in view with a 5% margin.
/// front looks north (from -y), back south, left east (from -x), right west, top down (north
/// up), iso from the south-west and above. Keeps `projection` and, for perspective, `fov_deg`.
/// @pre !scene.is_empty()
[[nodiscard]] Camera frame_view(const Box3& scene, ViewPreset preset, Projection projection,
                                double fov_deg, double aspect);

/// The default camera: frame_view(scene, iso, perspective, 50 degrees, aspect).
[[nodiscard]] Camera default_camera(const Box3& scene, double aspect);

}  // namespace roomcad
