// SPDX-License-Identifier: GPL-3.0-or-later
// The CPU renderer: draws a model into buffers the caller owns (a file writer, a test or the
// editor's window can share it).
//
// One frame: a shadow map per directional light (shadow_map.h), then the colour pass: the
// geometry pass (transform, frustum-cull clusters, clip, cull back faces, bin into 128-pixel
// tiles), and per tile, in parallel: rasterise depth and triangle ids (rasterizer.h), shade
// each visible sample once (shading.h), box-filter the k x k samples of each pixel. Every tile
// is one task writing only its own pixels, in scene order, so the image is identical at any
// thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "mesh/parts.h"
#include "mesh/solid_mesh.h"
#include "plan/plan.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/outdoors.h"
#include "render/scene.h"
#include "render/shading.h"
#include "render/shadow_map.h"

namespace roomcad {

/// Per pixel, the index into Model::objects of what is seen there; -1: background or a face
/// without object.
struct ObjectIdImage {
  int width = 0;
  int height = 0;
  std::vector<std::int32_t> ids;
  [[nodiscard]] std::int32_t at(int x, int y) const {
    return ids[static_cast<std::size_t>(y) * width + x];
  }
};

/// What render_model draws into. Resized by the renderer (kept when already the right size,
/// so a window can render into the same buffers frame after frame); contents replaced.
struct FrameBuffers {
  RgbImage color;
  FloatImage depth;       ///< metres along the view direction; 0 where nothing is drawn
  ObjectIdImage objects;  ///< what each pixel shows
};

/// Which of FrameBuffers' images a frame fills besides the colour. One left out is emptied
/// (0 x 0) and costs nothing: converting every depth to metres costs more than the resolve.
struct FrameOutputs {
  bool depth = true;
  bool object_ids = true;
};

/// Limits of check_render_options, so that no options can exhaust memory or run for days:
/// the frame buffers take 11 bytes a pixel (704 MiB at kMaxImagePixels), the colour pass's
/// time grows with the samples, and each of up to kMaxLights shadow maps takes 4 bytes a texel
/// (256 MiB at kMaxShadowResolution).
inline constexpr int kMaxImageSide = 16384;
inline constexpr long long kMaxImagePixels = 1LL << 26;   // 64 Mpixel: 8192 x 8192
inline constexpr long long kMaxImageSamples = 1LL << 28;  // 8192 x 8192 at ssaa 2
inline constexpr int kMaxShadowResolution = 8192;
inline constexpr int kMaxThreads = 256;

/// Which faces the colour pass skips before rasterising.
enum class FaceCull {
  none,        ///< nothing: every face is rasterised (to measure what culling saves)
  back_faces,  ///< one-sided faces turned away from the camera
  /// back faces, and every cell the camera's cell does not see through its portals
  /// (render/portal_walk.h; a model built with BuildOptions::cells, else as back_faces)
  portals,
  visibility,  ///< portals, then every face Makarov & Safin's visible-surface pre-pass
               ///< (render/visibility.h) finds unseen among those left
};

/// Everything a frame depends on besides the model. Designated initialisers welcome.
struct RenderOptions {
  int width = 1280;  ///< output pixels, 1 .. kMaxImageSide, width * height <= kMaxImagePixels
  int height = 720;
  std::optional<Camera> camera{};     ///< nullopt: frame the scene from `view`
  ViewPreset view = ViewPreset::iso;  ///< without a camera: frame_view() of the scene's
  Projection view_projection = Projection::perspective;  ///< bounds with this projection
  double view_fov_deg = 50.0;                            ///< and field of view (the default camera)
  ShadingMode shading = ShadingMode::phong;
  ShadowFilter shadows = ShadowFilter::pcf;
  int shadow_resolution = 1024;  ///< texels per side of each light's map, 1 .. 8192
  int ssaa = 1;                  ///< samples per pixel side: 1, 2 or 4 (see kMaxImageSamples)
  Color background{0xff, 0xff, 0xff};
  std::vector<Light> lights{};           ///< empty: default_light(); at most kMaxLights used
  GridLines grid{};                      ///< tile lines on floor faces
  Parts parts{};                         ///< which parts of the model to draw
  FaceCull cull = FaceCull::back_faces;  ///< the image is the same either way
  bool cull_frustum = true;              ///< skip clusters outside the view; same image either way
  int threads = 0;                       ///< 0: all cores; the image does not depend on it
  FrameOutputs outputs{};                ///< depth and object ids, or colour alone
  /// Keep the shadow maps of this thread's last frame while the scene (Scene::revision), the
  /// lights and the shadow resolution stay the same (a window redrawing as the camera moves:
  /// the maps are fitted to the scene, not the view). Same picture either way.
  bool reuse_shadow_maps = false;
  /// An outdoor picture (render/outdoors.h): render_model adds the ground and the obstructions
  /// to the model, the sky is the background (not `background`), and the default camera frames
  /// the model alone.
  std::optional<Outdoors> outdoors{};
};

/// What a frame cost, for --stats and benchmarks.
struct RenderStats {
  std::size_t triangles = 0;         ///< scene triangles submitted
  std::size_t screen_triangles = 0;  ///< after culling and clipping
  double shadow_ms = 0.0;            ///< all shadow maps
  double raster_ms = 0.0;            ///< the colour pass: geometry, raster, shading, resolve
  double frame_ms = 0.0;             ///< everything render_model did
  std::size_t culled_triangles = 0;  ///< skipped by FaceCull::visibility
  double cull_ms = 0.0;              ///< the visibility pre-pass (part of raster_ms)
  std::size_t cells_visited = 0;     ///< cells the portal walk reached (0: no walk)
  std::size_t drawn_triangles = 0;   ///< triangles submitted after the portal walk
};

/// Checks options. @return success, or a usage_error naming the option and its value.
[[nodiscard]] Status check_render_options(const RenderOptions& options);

/// Renders a model.
/// @param[in]  model    the meshes (their rc:object, rc:kind and rc:color face properties)
/// @param[in]  options  check_render_options(options).ok()
/// @param[out] out      resized and overwritten: colour, and depth and object ids as
///                      options.outputs asks (the others emptied)
/// @param[out] stats    timings and counts, or nullptr
/// @throws PreconditionError (usage_error) naming the option when check_render_options fails.
/// Cost: O(triangles + pixels * ssaa^2 * lights) plus O(triangles + resolution^2) per shadow map.
void render_model(const Model& model, const RenderOptions& options, FrameBuffers& out,
                  RenderStats* stats = nullptr);

/// The same for a scene already flattened (benchmarks and windows flatten once; the scene
/// already holds only the parts wanted, so options.parts is not used; with options.outdoors it
/// draws the sky, and the ground and obstructions only if add_outdoors added them, and no
/// outlines).
/// Both keep their working memory (binned triangles, about 80 bytes per triangle on screen,
/// and the shadow maps) in the calling thread between frames, so that redrawing allocates
/// nothing; it is freed when the thread ends.
void render_scene(const Scene& scene, const RenderOptions& options, FrameBuffers& out,
                  RenderStats* stats = nullptr);

/// The camera matrices a frame with these options uses, in world metres (tests cast rays
/// through them); the renderer draws with rebase_camera(frame_camera(...), scene.origin).
[[nodiscard]] CameraMatrices frame_camera(const Scene& scene, const RenderOptions& options);

}  // namespace roomcad
