// SPDX-License-Identifier: GPL-3.0-or-later
// The renderer as a whole: determinism across thread counts, shading modes, anti-aliasing,
// grid lines, caller-owned buffers, the images asked for and option errors.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "render/renderer.h"
#include "scene_support.h"

namespace roomcad {
namespace {

Model make_room() {
  Model m;
  m.objects = {"floor", "w1", "w2", "leaf"};
  test::add_floor(m.floor, {0.0, 0.0}, {8.0, 6.0}, 0);
  test::add_box(m.walls, {0.0, 0.0, 0.0}, {8.0, 0.25, 2.8}, 1);
  test::add_box(m.walls, {0.0, 0.25, 0.0}, {0.25, 6.0, 2.8}, 2);
  test::add_face(m.fixtures, {{5.0, 3.0, 0.0}, {5.9, 3.5, 0.0}, {5.9, 3.5, 2.1}, {5.0, 3.0, 2.1}},
                 3, FaceKind::door, {90, 60, 30});
  return m;
}

/// Unlit, unshadowed: each pixel shows a face's plain colour (or a blend of them at edges).
RenderOptions unlit_options(int width, int height) {
  return RenderOptions{.width = width,
                       .height = height,
                       .shading = ShadingMode::unlit,
                       .shadows = ShadowFilter::off};
}

/// Background, floor, wall and leaf colours of make_room().
const std::set<std::array<int, 3>> kPlainColours{
    {255, 255, 255}, {120, 180, 90}, {200, 60, 40}, {90, 60, 30}};

std::array<int, 3> pixel(const RgbImage& image, std::size_t i) {
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

TEST(Render, OutputIsIdenticalAtAnyThreadCount) {
  const Model m = make_room();
  FrameBuffers one, two, four;
  RenderOptions options{.width = 200, .height = 150, .ssaa = 2, .threads = 1};
  render_model(m, options, one);
  options.threads = 2;
  render_model(m, options, two);
  options.threads = 4;
  render_model(m, options, four);
  EXPECT_EQ(one.color.pixels, two.color.pixels);
  EXPECT_EQ(one.color.pixels, four.color.pixels);
  EXPECT_EQ(one.depth.values, two.depth.values);
  EXPECT_EQ(one.objects.ids, four.objects.ids);
}

TEST(Render, ImagesLeftOutAreEmptiedAndTheColourIsTheSame) {
  const Model m = make_room();
  FrameBuffers all, colour_only, ids_only;
  RenderOptions options{.width = 120, .height = 90};
  render_model(m, options, all);
  ASSERT_EQ(all.depth.values.size(), 120u * 90u);
  colour_only = all;  // filled buffers must be emptied, not left stale
  options.outputs = FrameOutputs{.depth = false, .object_ids = false};
  render_model(m, options, colour_only);
  EXPECT_EQ(colour_only.color.pixels, all.color.pixels);
  EXPECT_TRUE(colour_only.depth.values.empty());
  EXPECT_EQ(colour_only.depth.width, 0);
  EXPECT_TRUE(colour_only.objects.ids.empty());
  EXPECT_EQ(colour_only.objects.width, 0);
  options.outputs = FrameOutputs{.depth = false, .object_ids = true};
  render_model(m, options, ids_only);
  EXPECT_EQ(ids_only.objects.ids, all.objects.ids);
  EXPECT_TRUE(ids_only.depth.values.empty());
}

TEST(Render, UnlitDrawsPlainColoursAndLitModesDiffer) {
  const Model m = make_room();
  FrameBuffers unlit, flat, gouraud, phong;
  RenderOptions options = unlit_options(160, 120);
  render_model(m, options, unlit);
  std::set<std::array<int, 3>> colours;
  for (std::size_t i = 0; i < unlit.color.pixels.size(); i += 3)
    colours.insert(pixel(unlit.color, i));
  EXPECT_EQ(colours, kPlainColours);  // nothing else without shading, shadows or anti-aliasing
  // Seen along the sun's mirror direction over the floor, Phong shows a highlight inside the
  // floor's triangles that flat (per triangle) and Gouraud (per corner) shading do not.
  const glm::dvec3 centre(4.0, 3.0, 0.0), mirror = glm::normalize(glm::dvec3(-0.4, 0.5, 1.0));
  options.camera = test::look_from(centre + 6.0 * mirror, centre);
  options.shading = ShadingMode::flat;
  render_model(m, options, flat);
  options.shading = ShadingMode::gouraud;
  render_model(m, options, gouraud);
  options.shading = ShadingMode::phong;
  render_model(m, options, phong);
  EXPECT_NE(phong.color.pixels, flat.color.pixels);
  EXPECT_NE(phong.color.pixels, gouraud.color.pixels);
  FrameBuffers unlit_same_view;
  options.shading = ShadingMode::unlit;
  render_model(m, options, unlit_same_view);
  EXPECT_EQ(phong.objects.ids, unlit_same_view.objects.ids);  // shading never changes visibility
}

TEST(Render, SupersamplingBlendsEdgesOnly) {
  const Model m = make_room();
  RenderOptions options = unlit_options(160, 120);
  FrameBuffers aliased, smooth;
  render_model(m, options, aliased);
  options.ssaa = 4;
  render_model(m, options, smooth);
  int blended = 0, changed = 0;
  for (std::size_t i = 0; i < smooth.color.pixels.size(); i += 3) {
    blended += !kPlainColours.contains(pixel(smooth.color, i));
    changed += smooth.color.pixels[i] != aliased.color.pixels[i];
  }
  EXPECT_GT(blended, 50);
  EXPECT_LT(changed, 160 * 120 / 8);
}

TEST(Render, GridLinesDarkenTheFloorOnTileBoundaries) {
  const Model m = make_room();
  RenderOptions options = unlit_options(200, 150);
  options.view = ViewPreset::top;
  FrameBuffers plain, grid;
  render_model(m, options, plain);
  options.grid =
      GridLines{.enabled = true, .origin = {0.0, 0.0}, .cell_size = 1.0, .cells = {8, 6}};
  render_model(m, options, grid);
  int darkened = 0, floor = 0;
  for (std::size_t i = 0; i < grid.color.pixels.size(); i += 3) {
    if (plain.objects.ids[i / 3] != 0) continue;
    ++floor;
    darkened += grid.color.pixels[i] == 72;  // 120 * 0.6
  }
  // Lines 3 cm wide every metre, both ways: about 6% of the floor's pixel centres.
  EXPECT_GT(floor, 5000);
  EXPECT_GT(darkened, floor * 3 / 100);
  EXPECT_LT(darkened, floor * 12 / 100);
}

TEST(Render, ReusesCallerBuffersAndRejectsBadOptions) {
  const Model m = make_room();
  FrameBuffers out;
  render_model(m, RenderOptions{.width = 64, .height = 48}, out);
  const std::uint8_t* first = out.color.pixels.data();
  render_model(m, RenderOptions{.width = 64, .height = 48}, out);
  EXPECT_EQ(out.color.pixels.data(), first);  // same size: no reallocation
  EXPECT_EQ(out.objects.ids.size(), 64u * 48u);
  EXPECT_THROW(render_model(m, RenderOptions{.width = 0}, out), PreconditionError);
  EXPECT_THROW(render_model(m, RenderOptions{.ssaa = 3}, out), PreconditionError);
  const Status shadows = check_render_options(RenderOptions{.shadow_resolution = 0});
  EXPECT_EQ(shadows.code(), Code::usage_error);
  EXPECT_NE(shadows.message().find("0"), std::string::npos);
}

TEST(Render, EmptyModelGivesBackgroundOnly) {
  FrameBuffers out;
  render_model(Model{}, RenderOptions{.width = 32, .height = 32, .background = {1, 2, 3}}, out);
  for (std::size_t i = 0; i < out.color.pixels.size(); i += 3) {
    ASSERT_EQ(out.color.pixels[i + 2], 3);
  }
  for (int id : out.objects.ids) EXPECT_EQ(id, -1);
}

TEST(Render, PresetsFrameTheWholeScene) {
  const Scene scene = flatten_model(make_room());
  for (const ViewPreset preset : {ViewPreset::front, ViewPreset::back, ViewPreset::left,
                                  ViewPreset::right, ViewPreset::top, ViewPreset::iso}) {
    for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
      const Camera cam = frame_view(scene.bounds, preset, projection, 50.0, 4.0 / 3.0);
      const CameraMatrices m = make_camera_matrices(cam, scene.bounds, 4.0 / 3.0);
      for (const glm::vec3& c : scene.corners) {
        const glm::dvec4 p = m.view_projection * glm::dvec4(scene.origin + glm::dvec3(c), 1.0);
        EXPECT_GT(p.w, 0.0);
        EXPECT_LE(std::abs(p.x / p.w), 1.0);
        EXPECT_LE(std::abs(p.y / p.w), 1.0);
        EXPECT_GE(p.z / p.w, 0.0);
        EXPECT_LE(p.z / p.w, 1.0);
      }
    }
  }
  EXPECT_EQ(parse_view_preset("iso"), ViewPreset::iso);
  EXPECT_FALSE(parse_view_preset("Iso").has_value());
  EXPECT_EQ(parse_shading_mode("gouraud"), ShadingMode::gouraud);
  EXPECT_FALSE(parse_shading_mode("toon").has_value());
}

}  // namespace
}  // namespace roomcad
