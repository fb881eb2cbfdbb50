// SPDX-License-Identifier: GPL-3.0-or-later
// The model flattened once into triangle arrays the pipeline streams through.
//
// Normals: every triangle carries the unit normal of the planar polygon it came from, and its
// vertices share it. Smoothing across polygons would bend light around the corners of walls
// that are really flat and square, so Gouraud and Phong differ from flat shading only in where
// the light is evaluated (per vertex, per pixel), which matters for specular highlights.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/cells.h"
#include "mesh/parts.h"
#include "mesh/solid_mesh.h"
#include "render/camera.h"

namespace roomcad {

/// The passes of a frame a triangle takes part in (Cluster::passes): the model takes both; an
/// outdoor picture's ground is drawn but casts no shadow, its obstructions cast shadows but are
/// drawn in outline only (render/outdoors.h).
inline constexpr std::uint8_t kColourPass = 1;
inline constexpr std::uint8_t kShadowPass = 2;
inline constexpr std::uint8_t kAllPasses = kColourPass | kShadowPass;

/// A run of consecutive triangles with one bounding box, for frustum culling.
struct Cluster {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  Box3 bounds = empty_box3();  ///< relative to the scene's origin
  std::uint8_t passes = kAllPasses;
};

/// The model's cells (mesh/cells.h) and, per cell, the triangles that may be seen inside it:
/// runs in scene order, each within one cluster (render/scene_cells.h).
struct SceneCells {
  Cells cells;
  std::vector<std::vector<Cluster>> runs;  ///< per cell
  std::size_t indexed_triangles = 0;       ///< triangles appended later belong to no cell
};

/// Triangles in metres relative to `origin`, the centre of the model (float: positions within
/// a few km of it keep ~0.1 mm). Float world coordinates would lose that far from (0, 0): 1e6 m
/// away a float step is 6 cm, and shadow depths compared in it make acne.
/// The renderer moves its cameras and lights' maps into this frame (rebase_camera).
struct Scene {
  std::vector<glm::vec3> corners;       ///< 3 per triangle, counter-clockwise from outside,
                                        ///< relative to origin
  std::vector<glm::vec3> normals;       ///< 1 per triangle, unit
  std::vector<Color> colors;            ///< 1 per triangle
  std::vector<std::int32_t> objects;    ///< 1 per triangle: index into Model::objects or -1
  std::vector<FaceKind> kinds;          ///< 1 per triangle
  std::vector<std::uint8_t> two_sided;  ///< 1 per triangle: 1 = never back-face culled
  std::vector<Cluster> clusters;        ///< cover all triangles, in order
  Box3 bounds = empty_box3();           ///< of all triangles, world metres; empty if none
  glm::dvec3 origin{0.0};               ///< world position of the corners' (0, 0, 0)
  /// Changes whenever triangles are added (flatten_model, append_mesh, append_triangles): what a
  /// renderer keys the shadow maps it keeps between frames by (RenderOptions::reuse_shadow_maps).
  std::uint64_t revision = 0;
  /// The cells of the model drawn, when it was built with them and every part that closes
  /// them is drawn (walls, and slabs if they close cells); else null.
  std::shared_ptr<const SceneCells> cells;

  [[nodiscard]] std::size_t triangle_count() const { return normals.size(); }
};

/// Most triangles in one cluster: small enough to cull well, large enough to be cheap.
inline constexpr std::uint32_t kClusterSize = 256;

/// Flattens the chosen parts of a model: each polygon is triangulated (modeling's
/// triangulate_face), triangles keep the face's rc:object, rc:kind and rc:color (defaults when
/// a property is missing: -1, wall_face, grey). Walls and floor are one-sided (closed solid,
/// floor seen from above); fixtures are two-sided (thin leaves and panes).
/// Degenerate faces (zero area, fewer than 3 vertices) are skipped. The origin is the centre
/// of the bounding box of the parts' vertices (0 when there are none). With the model's cells
/// (Model::cells) and the parts that close them, the scene keeps them (index_cells).
/// @return the scene; clusters follow face order, one part after the other. O(n) in corners.
[[nodiscard]] Scene flatten_model(const Model& model, const Parts& parts = {});

/// Appends one mesh to a scene (what flatten_model does for each part).
/// @param[in,out] scene   grows, its corners relative to its origin (set before the first
///                        append); its clusters and bounds are updated
void append_mesh(const SolidMesh& mesh, bool two_sided, Scene& scene);

/// Appends triangles given by their world corners (3 a triangle, counter-clockwise seen from
/// outside) in clusters of their own taking part in `passes` only, with one colour and kind and
/// no object (-1), one-sided. O(corners).
void append_triangles(std::span<const glm::dvec3> corners, Color color, FaceKind kind,
                      std::uint8_t passes, Scene& scene);

/// @return the bounds, in the scene's frame (relative to its origin), of the clusters taking
///         part in all of `passes`; nullopt when every cluster does (then the scene's own
///         bounds are theirs). O(clusters).
[[nodiscard]] std::optional<Box3> pass_bounds(const Scene& scene, std::uint8_t passes);

/// @return the world bounds of the triangles that take part in both passes: the model itself,
///         what the default camera frames (scene.bounds when every triangle does). O(clusters).
[[nodiscard]] Box3 model_bounds(const Scene& scene);

}  // namespace roomcad
