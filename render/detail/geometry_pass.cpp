// SPDX-License-Identifier: GPL-3.0-or-later
// Vertex stage, culling, clipping and binning, in parallel over fixed chunks of the scene.
#include "render/detail/geometry_pass.h"

#include "core/assert.h"

#include <algorithm>

#include <tbb/parallel_for.h>

namespace roomcad::detail {
namespace {

/// 64 clusters of at most 256 triangles; clipping makes at most 7 of one, so a chunk's
/// screen triangles always fit the kLocalBits of an id.
constexpr std::size_t kClustersPerChunk = 64;
static_assert(kClustersPerChunk * kClusterSize * 7 < (1u << kLocalBits));

bool is_outside_frustum(const Box3& b, const glm::mat4& view_projection) {
  std::uint32_t all = 0x3f;
  for (int i = 0; i < 8 && all != 0; ++i) {
    const glm::vec3 c((i & 1) ? b.high[0] : b.low[0], (i & 2) ? b.high[1] : b.low[1],
                      (i & 4) ? b.high[2] : b.low[2]);
    all &= outcode(view_projection * glm::vec4(c, 1.f));
  }
  return all != 0;  // every corner outside one same plane
}

/// Keeps a set-up triangle unless it was culled or covers no sample (most triangles of a
/// large scene seen whole are such slivers: binning them would cost more than drawing).
void keep_if_visible(const std::optional<ScreenTriangle>& t, std::vector<ScreenTriangle>& out) {
  if (t && !covers_no_sample(*t)) out.push_back(*t);
}

/// Whether one-sided triangle i clearly faces away from the viewer: its normal turned from
/// the viewer by more than about 0.06 degrees past edge-on (nearly edge-on triangles are left
/// to set_up_triangle's exact screen-space test). O(1), no transform.
bool is_clearly_back_facing(const Scene& scene, std::uint32_t i, const glm::vec4& viewer) {
  const glm::vec3 to_viewer =
      glm::vec3(viewer) - viewer.w * scene.corners[3 * static_cast<std::size_t>(i)];
  const float facing = glm::dot(scene.normals[i], to_viewer);
  return facing < 0.f && facing * facing > 1e-6f * glm::dot(to_viewer, to_viewer);
}

/// Whether no corner of a triangle lies beyond a run's plane (RunView::beyond).
bool is_short_of(const glm::vec3* c, const glm::vec4& beyond) {
  auto past = [&](const glm::vec3& p) { return glm::dot(beyond, glm::vec4(p, 1.f)) > 0.f; };
  return !(past(c[0]) || past(c[1]) || past(c[2]));
}

/// Whether the triangle's clip-space corners all lie outside one side of the scissor
/// rectangle's view cone.
bool is_outside_scissor(const std::array<ClipVertex, 3>& v, const glm::vec4& s) {
  auto all = [&](auto outside) {
    return outside(v[0].position) && outside(v[1].position) && outside(v[2].position);
  };
  return all([&](const glm::vec4& p) { return p.x < s.x * p.w; }) ||
         all([&](const glm::vec4& p) { return p.x > s.z * p.w; }) ||
         all([&](const glm::vec4& p) { return p.y < s.y * p.w; }) ||
         all([&](const glm::vec4& p) { return p.y > s.w * p.w; });
}

void process_triangle(const Scene& scene, std::uint32_t i, const GeometryPass& pass,
                      const RunView* view, std::vector<ScreenTriangle>& out) {
  const bool one_sided = pass.cull_back_faces && !scene.two_sided[i];
  if (one_sided && is_clearly_back_facing(scene, i, pass.uniform_viewer)) return;
  const glm::vec3* c = &scene.corners[3 * static_cast<std::size_t>(i)];
  if (view && is_short_of(c, view->beyond)) return;
  const std::array<ClipVertex, 3> v{{
      {pass.uniform_view_projection * glm::vec4(c[0], 1.f), {0.f, 0.f}},
      {pass.uniform_view_projection * glm::vec4(c[1], 1.f), {1.f, 0.f}},
      {pass.uniform_view_projection * glm::vec4(c[2], 1.f), {0.f, 1.f}},
  }};
  if (view && is_outside_scissor(v, view->scissor)) return;
  const Culling culling = one_sided ? Culling::back_faces : Culling::none;
  const std::uint32_t c0 = outcode(v[0].position), c1 = outcode(v[1].position),
                      c2 = outcode(v[2].position);
  if (c0 & c1 & c2) return;  // wholly outside one plane
  if (!(c0 | c1 | c2)) {
    keep_if_visible(set_up_triangle(v, pass.width, pass.height, i, culling), out);
    return;
  }
  const ClipPolygon poly = clip_triangle(v);
  for (int k = 1; k + 1 < poly.count; ++k) {  // a fan keeps the polygon's orientation
    const std::array<ClipVertex, 3> piece{poly.vertices[0], poly.vertices[k], poly.vertices[k + 1]};
    keep_if_visible(set_up_triangle(piece, pass.width, pass.height, i, culling), out);
  }
}

/// The tiles a triangle's pixel box overlaps: [x0, x1] x [y0, y1], inclusive.
struct TileRange {
  int x0, y0, x1, y1;
};

TileRange tile_range(const ScreenTriangle& t, const BinnedTriangles& bins) {
  const auto [min_x, max_x] = std::minmax({t.x[0], t.x[1], t.x[2]});
  const auto [min_y, max_y] = std::minmax({t.y[0], t.y[1], t.y[2]});
  auto to_tile = [&](std::int32_t fixed, int pixels) {
    const int pixel = std::clamp(fixed >> kSubpixelBits, 0, pixels - 1);
    return pixel / bins.tile_size;
  };
  return {to_tile(min_x, bins.width), to_tile(min_y, bins.height), to_tile(max_x, bins.width),
          to_tile(max_y, bins.height)};
}

/// Calls `visit(tile)` for every tile of every triangle of chunk `c`, in order.
template <class Visit>
void for_each_binned(const BinnedTriangles& bins, std::size_t c, Visit&& visit) {
  const auto& chunk = bins.chunks[c];
  for (std::uint32_t local = 0; local < chunk.size(); ++local) {
    const TileRange r = tile_range(chunk[local], bins);
    for (int ty = r.y0; ty <= r.y1; ++ty)
      for (int tx = r.x0; tx <= r.x1; ++tx) visit(ty * bins.tiles_x + tx, local);
  }
}

/// Counting sort of (tile, id) pairs: per chunk counts, prefix sums in (tile, chunk) order,
/// then every chunk fills its own slots; the order is scene order within each tile.
void bin_triangles(BinnedTriangles& bins) {
  const std::size_t chunks = bins.chunks.size(), tiles = bins.tile_count();
  std::vector<std::uint32_t>& slot = bins.slots;
  slot.assign(chunks * tiles, 0);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    for_each_binned(bins, c, [&](int tile, std::uint32_t) { ++slot[c * tiles + tile]; });
  });
  bins.tile_offsets.assign(tiles + 1, 0);
  std::uint32_t running = 0;
  for (std::size_t t = 0; t < tiles; ++t) {
    bins.tile_offsets[t] = running;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::uint32_t count = slot[c * tiles + t];
      slot[c * tiles + t] = running;
      running += count;
    }
  }
  bins.tile_offsets[tiles] = running;
  bins.ids.resize(running);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    const auto chunk_bits = static_cast<std::uint32_t>(c) << kLocalBits;
    for_each_binned(bins, c, [&](int tile, std::uint32_t local) {
      bins.ids[slot[c * tiles + tile]++] = chunk_bits | local;
    });
  });
}

}  // namespace

std::size_t BinnedTriangles::triangle_count() const {
  std::size_t n = 0;
  for (const auto& chunk : chunks) n += chunk.size();
  return n;
}

void run_geometry_pass(const Scene& scene, const GeometryPass& pass, BinnedTriangles& bins) {
  bins.width = pass.width;
  bins.height = pass.height;
  bins.tile_size = pass.tile_size;
  bins.tiles_x = (pass.width + pass.tile_size - 1) / pass.tile_size;
  bins.tiles_y = (pass.height + pass.tile_size - 1) / pass.tile_size;
  const std::vector<Cluster>& clusters =
      pass.uniform_clusters ? *pass.uniform_clusters : scene.clusters;
  const std::size_t chunk_count = (clusters.size() + kClustersPerChunk - 1) / kClustersPerChunk;
  bins.chunks.resize(chunk_count);
  tbb::parallel_for(std::size_t{0}, chunk_count, [&](std::size_t c) {
    bins.chunks[c].clear();
    const std::size_t end = std::min(clusters.size(), (c + 1) * kClustersPerChunk);
    for (std::size_t k = c * kClustersPerChunk; k < end; ++k) {
      const Cluster& cluster = clusters[k];
      if ((cluster.passes & pass.pass) == 0) continue;
      if (pass.cull_frustum && is_outside_frustum(cluster.bounds, pass.uniform_view_projection)) {
        continue;
      }
      for (std::uint32_t i = cluster.first; i < cluster.first + cluster.count; ++i) {
        if (pass.uniform_draw && !pass.uniform_draw[i]) continue;
        process_triangle(scene, i, pass, pass.uniform_views ? &pass.uniform_views[k] : nullptr,
                         bins.chunks[c]);
      }
    }
  });
  bin_triangles(bins);
}

RasterTarget tile_rectangle(const BinnedTriangles& bins, int tile) {
  RC_ASSERT(tile >= 0 && tile < bins.tile_count(), "a tile of the frame");
  RasterTarget r;
  r.x0 = (tile % bins.tiles_x) * bins.tile_size;
  r.y0 = (tile / bins.tiles_x) * bins.tile_size;
  r.x1 = std::min(r.x0 + bins.tile_size, bins.width);
  r.y1 = std::min(r.y0 + bins.tile_size, bins.height);
  return r;
}

void rasterize_tile(const BinnedTriangles& bins, int tile, RasterTarget target) {
  RC_ASSERT(tile >= 0 && tile < bins.tile_count(), "a tile of the frame");
  for (std::uint32_t k = bins.tile_offsets[tile]; k < bins.tile_offsets[tile + 1]; ++k) {
    target.id_value = bins.ids[k];
    rasterize_triangle(bins.at(bins.ids[k]), target);
  }
}

}  // namespace roomcad::detail
