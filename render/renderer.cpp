// SPDX-License-Identifier: GPL-3.0-or-later
// One frame: shadow maps, then tiles rasterised, shaded and resolved in parallel.
#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <glm/gtc/type_ptr.hpp>

#include "render/detail/geometry_pass.h"
#include "render/detail/sample_shading.h"
#include "render/detail/shadow_pass.h"
#include "render/detail/wide_loops.h"
#include "render/portal_walk.h"
#include "render/visibility.h"

namespace roomcad {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Reversed-Z depth -> metres along the view direction, from the inverse projection:
/// distance = -(a * depth + b) / (c * depth + d); 0 stays 0 (nothing there).
struct DepthToDistance {
  double a = 0.0, b = 0.0, c = 0.0, d = 1.0;
  explicit DepthToDistance(const glm::dmat4& inverse_projection = glm::dmat4(1.0))
      : a(inverse_projection[2][2]),
        b(inverse_projection[3][2]),
        c(inverse_projection[2][3]),
        d(inverse_projection[3][3]) {}
  [[nodiscard]] float operator()(float depth) const {
    return depth <= 0.f ? 0.f : static_cast<float>(-(a * depth + b) / (c * depth + d));
  }
};

/// What a frame's shadow maps depend on (RenderOptions::reuse_shadow_maps).
struct ShadowKey {
  std::uint64_t scene_revision = 0;  ///< 0: no maps drawn yet
  std::vector<Light> lights;
  int resolution = 0;
  friend bool operator==(const ShadowKey&, const ShadowKey&) = default;
};

/// Memory a frame needs, kept between the frames of one calling thread (a window redrawing,
/// a benchmark): allocating and faulting in tens of megabytes a frame costs more than some
/// whole passes. Its contents never outlive a frame, so images do not depend on it.
struct FrameMemory {
  detail::BinnedTriangles bins;
  detail::BinnedTriangles shadow_bins;
  std::vector<ShadowMap> shadow_maps;
  ShadowKey shadow_key;  ///< what the shadow maps were drawn for
};

/// Everything the tile tasks read (the frame's `uniform_` state).
struct FrameContext {
  explicit FrameContext(FrameMemory& memory) : bins(memory.bins), shadow_maps(memory.shadow_maps) {}
  detail::BinnedTriangles& bins;
  std::vector<ShadowMap>& shadow_maps;
  detail::ShadeUniforms shade;
  DepthToDistance depth_to_distance;
  int ssaa = 1;
  FrameOutputs outputs;
};

/// @param[in] cam     in the scene's frame (rebase_camera)
/// @param[in] origin  the scene's origin: the grid moves into its frame too
ShadingUniforms make_uniforms(const RenderOptions& options, const CameraMatrices& cam,
                              const std::vector<Light>& lights, const glm::dvec3& origin) {
  ShadingUniforms u;
  u.mode = options.shading;
  u.light_count = static_cast<int>(std::min<std::size_t>(lights.size(), kMaxLights));
  for (int k = 0; k < u.light_count; ++k) u.lights[k] = to_shading_light(lights[k]);
  u.eye = glm::vec3(cam.eye);
  u.forward = glm::vec3(cam.forward);
  u.orthographic = cam.orthographic;
  u.grid = options.grid;
  u.grid.origin -= glm::dvec2(origin);
  return u;
}

/// Writes one row of output pixels of a tile: colour averaged over their k x k samples; depth
/// and object id of the sample nearest each pixel's centre (up and left of it for even k).
/// K is the frame's ssaa, a template parameter so that the sample loops unroll; each output
/// is its own loop over the row, so that the colour and depth loops vectorise.
template <int K>
void resolve_row(const FrameContext& f, const RasterTarget& t, const glm::vec3* rgb, int oy,
                 FrameBuffers& out) {
  constexpr int centre = (K - 1) / 2;
  constexpr float scale = 255.f / static_cast<float>(K * K);
  const int w = t.x1 - t.x0, ox0 = t.x0 / K, n = w / K;
  const glm::vec3* samples = rgb + static_cast<std::ptrdiff_t>(oy * K - t.y0) * w;
  std::uint8_t* color = out.color.at(ox0, oy);
  if constexpr (K == 1) {  // one sample a pixel: the row's floats in order, a loop that vectorises
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "glm::vec3 arrays are packed floats");
    const float* channels = glm::value_ptr(samples[0]);
    for (int c = 0; c < 3 * n; ++c) {
      color[c] = static_cast<std::uint8_t>(channels[c] * scale + 0.5f);
    }
  } else {
    for (int j = 0; j < n; ++j) {
      glm::vec3 sum(0.f);
      for (int sy = 0; sy < K; ++sy)
        for (int sx = 0; sx < K; ++sx) sum += samples[sy * w + j * K + sx];
      for (int ch = 0; ch < 3; ++ch) {
        color[3 * j + ch] = static_cast<std::uint8_t>(sum[ch] * scale + 0.5f);
      }
    }
  }
  const std::ptrdiff_t centre_row =
      static_cast<std::ptrdiff_t>(oy * K + centre - t.y0) * w + centre;
  if (f.outputs.depth) {
    const float* depth = t.depth + centre_row;
    float* distance = &out.depth.at(ox0, oy);
    for (int j = 0; j < n; ++j) distance[j] = f.depth_to_distance(depth[j * K]);
  }
  if (!f.outputs.object_ids) return;
  const std::uint32_t* ids = t.ids + centre_row;
  std::int32_t* objects = &out.objects.ids[static_cast<std::size_t>(oy) * out.objects.width + ox0];
  std::uint32_t last_id = kNoTriangle;
  std::int32_t last_object = -1;
  for (int j = 0; j < n; ++j) {
    if (ids[j * K] != last_id) {  // neighbours mostly show the same triangle
      last_id = ids[j * K];
      last_object =
          last_id == kNoTriangle ? -1 : f.shade.scene->objects[f.bins.at(last_id).triangle];
    }
    objects[j] = last_object;
  }
}

/// Writes the output pixels of one tile (see resolve_row).
template <int K>
void resolve_tile(const FrameContext& f, const RasterTarget& t, const std::vector<glm::vec3>& rgb,
                  FrameBuffers& out) {
  for (int oy = t.y0 / K; oy < t.y1 / K; ++oy) resolve_row<K>(f, t, rgb.data(), oy, out);
}

ROOMCAD_WIDE_LOOPS void render_tile(const FrameContext& f, int tile, FrameBuffers& out) {
  RasterTarget t = detail::tile_rectangle(f.bins, tile);
  const std::size_t n = static_cast<std::size_t>(t.x1 - t.x0) * (t.y1 - t.y0);
  thread_local std::vector<float> depth;  // reused: tiles are many and small
  thread_local std::vector<std::uint32_t> ids;
  thread_local std::vector<glm::vec3> rgb;
  depth.assign(n, 0.f);
  ids.assign(n, kNoTriangle);
  rgb.resize(n);  // every sample is written by shade_tile
  t.depth = depth.data();
  t.ids = ids.data();
  detail::rasterize_tile(f.bins, tile, t);
  detail::shade_tile(f.shade, t, rgb.data());
  switch (f.ssaa) {
    case 1: return resolve_tile<1>(f, t, rgb, out);
    case 2: return resolve_tile<2>(f, t, rgb, out);
    default: return resolve_tile<4>(f, t, rgb, out);  // check_render_options: 1, 2 or 4
  }
}

/// Sizes the images the frame fills and empties the others (see FrameOutputs).
void size_buffers(int width, int height, FrameOutputs outputs, FrameBuffers& out) {
  if (out.color.width != width || out.color.height != height) out.color = RgbImage(width, height);
  if (!outputs.depth) {
    out.depth = FloatImage();
  } else if (out.depth.width != width || out.depth.height != height) {
    out.depth = FloatImage(width, height);
  }
  out.objects.width = outputs.object_ids ? width : 0;
  out.objects.height = outputs.object_ids ? height : 0;
  out.objects.ids.resize(static_cast<std::size_t>(out.objects.width) * out.objects.height);
}

void render_frame(const Scene& scene, const RenderOptions& options, FrameBuffers& out,
                  RenderStats& stats) {
  const std::vector<Light> lights =
      options.lights.empty() ? std::vector<Light>{default_light()} : options.lights;
  thread_local FrameMemory memory;
  FrameContext f(memory);
  f.shade.scene = &scene;
  f.shade.bins = &f.bins;
  f.shade.shadow_maps = &f.shadow_maps;
  f.ssaa = options.ssaa;
  f.outputs = options.outputs;
  f.shade.filter = options.shadows;
  f.shade.background = to_unit_rgb(options.background);
  if (options.outdoors) {
    f.shade.background = to_unit_rgb(options.outdoors->sky_top);
    f.shade.sky_bottom = to_unit_rgb(options.outdoors->sky_horizon);
    f.shade.sky_rows = options.height * options.ssaa;
  }
  const auto shadow_start = Clock::now();
  const std::size_t maps =
      options.shadows == ShadowFilter::off ? 0 : std::min<std::size_t>(lights.size(), kMaxLights);
  ShadowKey key{scene.revision,
                {lights.begin(), lights.begin() + std::ptrdiff_t(maps)},
                options.shadow_resolution};
  if (!(options.reuse_shadow_maps && key == memory.shadow_key && scene.revision != 0)) {
    f.shadow_maps.resize(maps);
    for (std::size_t k = 0; k < maps; ++k) {
      detail::render_shadow_map_into(scene, lights[k], options.shadow_resolution, f.shadow_maps[k],
                                     memory.shadow_bins);
    }
    memory.shadow_key = std::move(key);
  }
  stats.shadow_ms = ms_since(shadow_start);
  const auto raster_start = Clock::now();
  // Everything from here on works in the scene's frame, where float keeps its precision.
  const CameraMatrices cam = rebase_camera(frame_camera(scene, options), scene.origin);
  f.shade.shading = make_uniforms(options, cam, lights, scene.origin);
  f.depth_to_distance = DepthToDistance(glm::inverse(cam.projection));
  std::optional<PortalWalk> walk;
  if (options.cull == FaceCull::portals || options.cull == FaceCull::visibility) {
    walk = walk_portals(scene, cam);
    if (walk) {
      stats.cells_visited = walk->cells_visited;
      for (const Cluster& run : walk->runs) stats.drawn_triangles += run.count;
    }
  }
  std::vector<std::uint8_t> seen;
  // The pre-pass knows no passes: shadow-only obstructions would hide what is behind them, so a
  // scene with some is culled by faces alone (the same picture either way).
  const bool all_drawn = std::all_of(scene.clusters.begin(), scene.clusters.end(),
                                     [](const Cluster& c) { return c.passes & kColourPass; });
  if (options.cull == FaceCull::visibility && all_drawn) {
    const auto cull_start = Clock::now();
    VisibilityResult v = find_visible_faces(scene, {.camera = cam,
                                                    .width = options.width * options.ssaa,
                                                    .height = options.height * options.ssaa,
                                                    .clusters = walk ? &walk->runs : nullptr,
                                                    .views = walk ? walk->views.data() : nullptr});
    stats.culled_triangles = scene.triangle_count() - v.visible_count;
    seen = std::move(v.visible);
    stats.cull_ms = ms_since(cull_start);
  }
  detail::run_geometry_pass(
      scene,
      detail::GeometryPass{.uniform_view_projection = glm::mat4(cam.view_projection),
                           .width = options.width * options.ssaa,
                           .height = options.height * options.ssaa,
                           .tile_size = 128,
                           .cull_back_faces = options.cull != FaceCull::none,
                           .cull_frustum = options.cull_frustum,
                           .uniform_draw = seen.empty() ? nullptr : seen.data(),
                           .uniform_clusters = walk ? &walk->runs : nullptr,
                           .uniform_views = walk ? walk->views.data() : nullptr,
                           .uniform_viewer = cam.orthographic
                                                 ? glm::vec4(-glm::vec3(cam.forward), 0.f)
                                                 : glm::vec4(glm::vec3(cam.eye), 1.f)},
      f.bins);
  size_buffers(options.width, options.height, options.outputs, out);
  tbb::parallel_for(0, f.bins.tile_count(), [&](int tile) { render_tile(f, tile, out); });
  stats.raster_ms = ms_since(raster_start);
  stats.triangles = scene.triangle_count();
  stats.screen_triangles = f.bins.triangle_count();
}

}  // namespace

Status check_render_options(const RenderOptions& o) {
  if (o.width < 1 || o.width > kMaxImageSide || o.height < 1 || o.height > kMaxImageSide) {
    return Status::failure(Code::usage_error,
                           fmt::format("width x height is {} x {}; each must be 1 to {}", o.width,
                                       o.height, kMaxImageSide));
  }
  const long long pixels = static_cast<long long>(o.width) * o.height;
  if (pixels > kMaxImagePixels) {
    return Status::failure(
        Code::usage_error,
        fmt::format("width x height is {} x {} = {} pixels; at most {} are rendered", o.width,
                    o.height, pixels, kMaxImagePixels));
  }
  if (o.ssaa != 1 && o.ssaa != 2 && o.ssaa != 4) {
    return Status::failure(Code::usage_error,
                           fmt::format("ssaa is {}; it must be 1, 2 or 4", o.ssaa));
  }
  if (pixels * o.ssaa * o.ssaa > kMaxImageSamples) {
    return Status::failure(
        Code::usage_error,
        fmt::format("width x height x ssaa^2 is {} x {} x {} = {} samples; at most {}", o.width,
                    o.height, o.ssaa * o.ssaa, pixels * o.ssaa * o.ssaa, kMaxImageSamples));
  }
  if (o.shadow_resolution < 1 || o.shadow_resolution > kMaxShadowResolution) {
    return Status::failure(Code::usage_error,
                           fmt::format("shadow resolution is {}; it must be 1 to {}",
                                       o.shadow_resolution, kMaxShadowResolution));
  }
  if (o.threads < 0 || o.threads > kMaxThreads) {
    return Status::failure(
        Code::usage_error,
        fmt::format("threads is {}; it must be 0 (all cores) to {}", o.threads, kMaxThreads));
  }
  const double fov = o.camera ? o.camera->fov_deg : o.view_fov_deg;
  if (!(fov > 0.0 && fov < 180.0)) {
    return Status::failure(
        Code::usage_error,
        fmt::format("field of view is {} degrees; it must be between 0 and 180", fov));
  }
  if (o.camera && o.camera->projection == Projection::orthographic &&
      !(o.camera->view_height > 0.0 && std::isfinite(o.camera->view_height))) {
    return Status::failure(Code::usage_error,
                           fmt::format("camera '{}' view height is {} m; it must be positive",
                                       o.camera->id, o.camera->view_height));
  }
  return Status::success();
}

CameraMatrices frame_camera(const Scene& scene, const RenderOptions& options) {
  const double aspect = static_cast<double>(options.width) / options.height;
  Box3 bounds = scene.bounds, framed = model_bounds(scene);
  if (is_empty(bounds)) add_point(bounds, glm::dvec3(0.0));  // nothing to frame: look at the origin
  if (is_empty(framed)) framed = bounds;
  const Camera camera = options.camera ? *options.camera
                                       : frame_view(framed, options.view, options.view_projection,
                                                    options.view_fov_deg, aspect);
  return make_camera_matrices(camera, bounds, aspect);
}

void render_scene(const Scene& scene, const RenderOptions& options, FrameBuffers& out,
                  RenderStats* stats) {
  throw_if_failed(check_render_options(options), "render");
  const auto start = Clock::now();
  RenderStats local;
  const int threads = options.threads > 0 ? options.threads : tbb::task_arena::automatic;
  tbb::task_arena arena(threads);
  arena.execute([&] { render_frame(scene, options, out, local); });
  local.frame_ms = ms_since(start);
  if (stats) *stats = local;
}

void render_model(const Model& model, const RenderOptions& options, FrameBuffers& out,
                  RenderStats* stats) {
  const auto start = Clock::now();
  Scene scene = flatten_model(model, options.parts);
  if (options.outdoors) add_outdoors(*options.outdoors, scene);
  // the obstructions' outlines are drawn over the frame, hidden by its depth
  const bool outlines = options.outdoors && !options.outdoors->obstructions.empty();
  RenderOptions frame = options;
  frame.outputs.depth = options.outputs.depth || outlines;
  render_scene(scene, frame, out, stats);
  if (outlines) {
    outline_obstructions(*options.outdoors, frame_camera(scene, options), out.depth, out.color);
    if (!options.outputs.depth) out.depth = FloatImage();
  }
  if (stats) stats->frame_ms = ms_since(start);
}

}  // namespace roomcad
