// SPDX-License-Identifier: GPL-3.0-or-later
// Views of line drawings and their layout on paper.
#include "render/line_drawing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/box.h"
#include "render/detail/scale_bar.h"

namespace roomcad {
namespace {

using detail::kSheetFooterMm;
using detail::kSheetMarginMm;
constexpr double kPerspectiveWidthMm = 270.0;
constexpr double kPerspectiveAspect = 1.5;

glm::dvec3 to_glm(const Vec3& v) { return {v.x, v.y, v.z}; }

/// Picture -> paper: a scale and the picture point at the paper's top-left corner.
struct PictureToPaper {
  double mm_per_unit = 1.0;
  Point2 origin;  ///< picture point drawn at paper (left, top)
  double left = 0.0, top = 0.0;
  [[nodiscard]] Point2 map(Point2 p) const {
    return {left + (p.x - origin.x) * mm_per_unit, top + (origin.y - p.y) * mm_per_unit};
  }
};

/// Liang-Barsky clip of a segment to a box. @return false if nothing is inside.
bool clip_to_box(Segment2& s, const Box2& box) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const std::array<double, 4> p{-dx, dx, -dy, dy};
  const std::array<double, 4> q{s.a.x - box.min_x, box.max_x - s.a.x, s.a.y - box.min_y,
                                box.max_y - s.a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0.0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
  }
  if (t0 >= t1) return false;
  const Point2 a = s.a;
  s.a = {a.x + t0 * dx, a.y + t0 * dy};
  s.b = {a.x + t1 * dx, a.y + t1 * dy};
  return true;
}

void map_lines(const std::vector<Segment2>& in, const PictureToPaper& m, const Box2* frame,
               std::vector<PaperLine>& out) {
  for (Segment2 s : in) {
    if (frame && !clip_to_box(s, *frame)) continue;
    out.push_back({m.map(s.a), m.map(s.b)});
  }
}

Box2 picture_box(const HiddenLineResult& r) {
  Box2 box = empty_box2();
  for (const auto* lines : {&r.visible, &r.hidden})
    for (const Segment2& s : *lines)
      for (const Point2 p : {s.a, s.b}) add_point(box, p.x, p.y);
  if (is_empty(box)) add_point(box, 0.0, 0.0);
  return box;
}

/// Orthographic layout: the picture at 1:scale with margins, a scale bar and the title below.
PictureToPaper lay_out_to_scale(const Box2& box, double scale, LineDrawing& out) {
  PictureToPaper m{.mm_per_unit = 1000.0 / scale,
                   .origin = {box.min_x, box.max_y},
                   .left = kSheetMarginMm,
                   .top = kSheetMarginMm};
  out.width = std::max(120.0, (box.max_x - box.min_x) * m.mm_per_unit + 2.0 * kSheetMarginMm);
  out.height = (box.max_y - box.min_y) * m.mm_per_unit + 2.0 * kSheetMarginMm + kSheetFooterMm;
  detail::add_scale_bar(out.width, out.height, m.mm_per_unit,
                        {out.scale_bar_black, out.scale_bar_white, out.labels});
  return m;
}

/// Perspective layout: the field of view (vertical fov, aspect 3:2) fills a fixed page.
PictureToPaper lay_out_frame(const LineView& view, Box2& frame, LineDrawing& out) {
  const double half_h = std::tan(view.fov_deg * M_PI / 360.0);
  const double half_w = half_h * kPerspectiveAspect;
  frame = {-half_w, -half_h, half_w, half_h, 0};
  PictureToPaper m{.mm_per_unit = kPerspectiveWidthMm / (2.0 * half_w),
                   .origin = {-half_w, half_h},
                   .left = kSheetMarginMm,
                   .top = kSheetMarginMm};
  out.width = kPerspectiveWidthMm + 2.0 * kSheetMarginMm;
  out.height = kPerspectiveWidthMm / kPerspectiveAspect + 2.0 * kSheetMarginMm + kSheetFooterMm;
  const Point2 c[4] = {m.map({-half_w, -half_h}), m.map({half_w, -half_h}), m.map({half_w, half_h}),
                       m.map({-half_w, half_h})};
  for (int i = 0; i < 4; ++i) out.frame.push_back({c[i], c[(i + 1) % 4]});
  return m;
}

}  // namespace

std::optional<LineView> preset_line_view(std::string_view name) {
  struct Preset {
    std::string_view name, title;
    glm::dvec3 forward;
  };
  static const std::array<Preset, 5> presets{{
      {"north", "North elevation (looking south)", {0, -1, 0}},
      {"south", "South elevation (looking north)", {0, 1, 0}},
      {"east", "East elevation (looking west)", {-1, 0, 0}},
      {"west", "West elevation (looking east)", {1, 0, 0}},
      {"iso", "Isometric from the south-west", {1, 1, -1}},
  }};
  for (const Preset& p : presets) {
    if (p.name == name) return LineView{.name = std::string(p.title), .forward = p.forward};
  }
  return std::nullopt;
}

LineView camera_line_view(const Camera& camera) {
  LineView v;
  v.name = fmt::format("Camera {}", camera.id);
  v.perspective = camera.projection == Projection::perspective;
  v.eye = to_glm(camera.eye);
  v.forward = to_glm(camera.target) - v.eye;
  if (glm::length(v.forward) == 0.0) v.forward = {0, 1, 0};  // as make_camera_matrices
  v.up = to_glm(camera.up);
  if (glm::length(glm::cross(glm::normalize(v.forward), v.up)) < 1e-9) v.up = {0, 1, 0};
  v.fov_deg = camera.fov_deg;
  return v;
}

LineDrawing draw_line_view(const Model& model, const LineView& view,
                           const LineDrawingOptions& options, const std::string& title) {
  if (!(options.scale >= 1.0 && options.scale <= 10000.0)) {
    throw PreconditionError(
        fmt::format("draw_line_view: scale 1:{} is not 1:1 .. 1:10000", options.scale),
        Code::usage_error);
  }
  LineDrawing out;
  out.stats = remove_hidden_lines(model, options.parts, view);
  Box2 frame = empty_box2();
  const PictureToPaper m = view.perspective
                               ? lay_out_frame(view, frame, out)
                               : lay_out_to_scale(picture_box(out.stats), options.scale, out);
  const Box2* clip = view.perspective ? &frame : nullptr;
  map_lines(out.stats.visible, m, clip, out.visible);
  if (options.hidden == HiddenLines::dashed) map_lines(out.stats.hidden, m, clip, out.hidden);
  const std::string scale_text = view.perspective ? std::string("perspective, not to scale")
                                                  : fmt::format("scale 1:{}", options.scale);
  out.labels.push_back({{kSheetMarginMm, out.height - kSheetFooterMm + 16.0},
                        fmt::format("{}, {}, {}", title, view.name, scale_text),
                        3.5,
                        0.0,
                        TextAnchor::start});
  return out;
}

}  // namespace roomcad
