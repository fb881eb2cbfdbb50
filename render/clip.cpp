// SPDX-License-Identifier: GPL-3.0-or-later
// Sutherland-Hodgman clipping of one triangle against the six clip-space planes.
#include "render/clip.h"

namespace roomcad {
namespace {

constexpr int kPlaneCount = 6;

/// Signed distance-like value of `p` to plane `plane`: >= 0 inside.
float plane_value(const glm::vec4& p, int plane) {
  switch (plane) {
    case 0: return p.w + p.x;
    case 1: return p.w - p.x;
    case 2: return p.w + p.y;
    case 3: return p.w - p.y;
    case 4: return p.z;         // far (reversed-Z: depth 0)
    default: return p.w - p.z;  // near (depth 1)
  }
}

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t) {
  return {a.position + (b.position - a.position) * t, a.source + (b.source - a.source) * t};
}

/// Clips polygon `in` against one plane into `out`.
void clip_against(const ClipPolygon& in, int plane, ClipPolygon& out) {
  out.count = 0;
  for (int i = 0; i < in.count; ++i) {
    const ClipVertex& a = in.vertices[i];
    const ClipVertex& b = in.vertices[(i + 1) % in.count];
    const float da = plane_value(a.position, plane);
    const float db = plane_value(b.position, plane);
    if (da >= 0.f) out.vertices[out.count++] = a;
    if ((da >= 0.f) != (db >= 0.f)) {
      out.vertices[out.count++] = lerp(a, b, da / (da - db));
    }
  }
  if (out.count < 3) out.count = 0;
}

}  // namespace

std::uint32_t outcode(const glm::vec4& p) {
  std::uint32_t code = 0;
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (plane_value(p, plane) < 0.f) code |= 1u << plane;
  }
  return code;
}

ClipPolygon clip_triangle(const std::array<ClipVertex, 3>& triangle) {
  ClipPolygon a;
  ClipPolygon b;
  a.vertices[0] = triangle[0];
  a.vertices[1] = triangle[1];
  a.vertices[2] = triangle[2];
  a.count = 3;
  const std::uint32_t any_out =
      outcode(triangle[0].position) | outcode(triangle[1].position) | outcode(triangle[2].position);
  for (int plane = 0; plane < kPlaneCount && a.count > 0; ++plane) {
    if (!(any_out & (1u << plane))) continue;  // all corners inside: nothing to cut
    clip_against(a, plane, b);
    a = b;
  }
  return a;
}

}  // namespace roomcad
