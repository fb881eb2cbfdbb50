// SPDX-License-Identifier: GPL-3.0-or-later
// The outside reference: the same room-grid meshes drawn by Mesa's llvmpipe through OSMesa at
// 1920 x 1080: the mesh is uploaded once into vertex buffers, and a frame is glClear +
// glDrawArrays with the depth test + glFinish (one pass, no shadows, flat vertex colours,
// default state otherwise: no face culling). llvmpipe's threads: LP_NUM_THREADS (default: all
// cores). Built only where OSMesa is installed (libosmesa6-dev).
#include <GL/osmesa.h>
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "bench/room_grid.h"
#include "render/renderer.h"

namespace roomcad {
namespace {

constexpr int kWidth = 1920;
constexpr int kHeight = 1080;

using GenBuffers = void (*)(GLsizei, GLuint*);
using BindBuffer = void (*)(GLenum, GLuint);
using BufferData = void (*)(GLenum, GLsizeiptr, const void*, GLenum);
constexpr GLenum kArrayBuffer = 0x8892;  // GL_ARRAY_BUFFER
constexpr GLenum kStaticDraw = 0x88E4;   // GL_STATIC_DRAW

/// An OSMesa context drawing into a 1920 x 1080 RGBA buffer, made current.
struct Context {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> pixels = std::vector<unsigned char>(kWidth * kHeight * 4);
  Context() {
    context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!context || !OSMesaMakeCurrent(context, pixels.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
      std::fprintf(stderr, "osmesa_bench: cannot create an OSMesa context\n");
      std::exit(2);
    }
  }
  ~Context() { OSMesaDestroyContext(context); }
};

/// Uploads a scene's triangles (positions and colours) into two vertex buffers, bound for
/// glDrawArrays. @return the vertex count.
GLsizei upload(const Scene& scene) {
  const auto gen = reinterpret_cast<GenBuffers>(OSMesaGetProcAddress("glGenBuffers"));
  const auto bind = reinterpret_cast<BindBuffer>(OSMesaGetProcAddress("glBindBuffer"));
  const auto data = reinterpret_cast<BufferData>(OSMesaGetProcAddress("glBufferData"));
  std::vector<unsigned char> colors;
  for (std::size_t t = 0; t < scene.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      colors.insert(colors.end(), {scene.colors[t].r, scene.colors[t].g, scene.colors[t].b});
  GLuint buffers[2];
  gen(2, buffers);
  bind(kArrayBuffer, buffers[0]);
  data(kArrayBuffer, static_cast<GLsizeiptr>(scene.corners.size() * sizeof(glm::vec3)),
       scene.corners.data(), kStaticDraw);
  glVertexPointer(3, GL_FLOAT, 0, nullptr);
  bind(kArrayBuffer, buffers[1]);
  data(kArrayBuffer, static_cast<GLsizeiptr>(colors.size()), colors.data(), kStaticDraw);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  return static_cast<GLsizei>(scene.corners.size());
}

/// The renderer's default camera, as a conventional OpenGL projection (far plane fitted).
void load_camera(const Scene& scene) {
  const double aspect = static_cast<double>(kWidth) / kHeight;
  const Camera cam = default_camera(scene.bounds, aspect);
  const glm::dvec3 eye(cam.eye.x, cam.eye.y, cam.eye.z),
      target(cam.target.x, cam.target.y, cam.target.z);
  const double far =
      glm::length(eye - target) + glm::length(high_corner(scene.bounds) - low_corner(scene.bounds));
  const glm::mat4 projection = glm::perspective(glm::radians(cam.fov_deg), aspect, 0.05, far);
  // The scene's corners are relative to its origin (scene.h).
  const glm::mat4 view =
      glm::translate(glm::lookAt(eye, target, glm::dvec3(0, 0, 1)), scene.origin);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(glm::value_ptr(projection));
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(glm::value_ptr(view));
  glViewport(0, 0, kWidth, kHeight);
  glEnable(GL_DEPTH_TEST);
  glClearColor(1.f, 1.f, 1.f, 1.f);
}

/// Arg: rooms per side (the same grids as render_bench's BM_Frame1080p).
void BM_LlvmpipeFrame1080p(benchmark::State& state) {
  static Context context;
  const Scene scene = flatten_model(samples::make_room_grid(static_cast<int>(state.range(0))));
  const GLsizei vertices = upload(scene);
  load_camera(scene);
  for (auto _ : state) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, vertices);
    glFinish();
  }
  state.counters["triangles"] = static_cast<double>(scene.triangle_count());
}
BENCHMARK(BM_LlvmpipeFrame1080p)
    ->Arg(2)
    ->Arg(10)
    ->Arg(25)
    ->Arg(50)
    ->Arg(82)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.3);

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
