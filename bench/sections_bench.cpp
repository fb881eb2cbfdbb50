// SPDX-License-Identifier: GPL-3.0-or-later
// The sections of the general path's primitives by the planes that cross them
// (solid/detail/general_path/primitive_section.h) on real homes: made from the primitive's crossing
// edges (section_of) against clipped from the box's square by every face (how each section was
// made before, and section_of's way where a vertex lies on the plane). The pairs are every
// primitive of the home with every plane of a face of another whose box it meets and that has
// its vertices on both sides: the sections the build makes, and the others of those planes.
// The two ways take turns in one process (one pass over the pairs each, then again), so the
// machine's drift from one minute to the next falls on both alike. Prints per home the pairs,
// the share section_of made from the crossings, the fastest and the median pass of each way,
// the median of the per-round ratios (crossings / clipped: quote it), and whether every section
// has the same lines both ways.
//
//   sections_bench [--homes DIR]... [--rounds N]
//
// Homes: examples/sweethome3d/ and the generated 504-wall tower (testing/tower_plan.h); the
// walls and slabs as `roomcad build --force --parts walls,slabs` builds them; 40 rounds unless
// told. One thread.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bench/bundled_homes.h"
#include "geometry/joins.h"
#include "solid/detail/frames/buildable_plan.h"
#include "solid/detail/general_path/primitive_section.h"

namespace {

using namespace roomcad;
using namespace roomcad::detail;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2.0;
}

// A home's primitives in their own plane set, and the (primitive, plane) pairs that cross.
struct Sections {
  PlaneSet set;
  BoxPlanes box;
  std::vector<Primitive> prims;
  std::vector<std::pair<std::size_t, PlaneRef>> pairs;
};

void make_sections(const Plan& input, Sections& s) {
  const BuildablePlan buildable = make_buildable(input);
  const Plan& plan = buildable.plan;
  const std::vector<WallFrame> frames =
      make_wall_frames(plan, find_joins(plan), buildable.through_mitre);
  const std::vector<SlabFrame> slabs = make_slab_frames(plan, frames);
  std::vector<const WallFrame*> walls;
  for (const WallFrame& f : frames) walls.push_back(&f);
  std::vector<const SlabFrame*> slab_ptrs;
  for (const SlabFrame& f : slabs) slab_ptrs.push_back(&f);
  s.box = add_box_planes(s.set, largest_coordinate(walls, slab_ptrs));
  s.prims = make_primitives(s.set, s.box, walls, slab_ptrs);
  std::map<PlaneId, std::pair<std::size_t, Box3>>
      planes;  // per plane: a primitive with a face on it
  for (std::size_t p = 0; p < s.prims.size(); ++p)
    for (const PlanePolygon& f : s.prims[p].faces)
      planes.try_emplace(f.plane.id, p, box_of(f.vertices));
  const IntervalScope intervals;
  for (const auto& [id, owner] : planes)
    for (std::size_t p = 0; p < s.prims.size(); ++p) {
      if (p == owner.first || !boxes_meet(owner.second, s.prims[p].box)) continue;
      bool below = false, above = false;
      for (const XPoint& v : s.prims[p].vertices) {
        const int side_of_v = side(s.set, {id, 1}, v);
        below = below || side_of_v < 0, above = above || side_of_v > 0;
      }
      if (below && above) s.pairs.emplace_back(p, PlaneRef{id, 1});
    }
}

// One pass over the pairs, one way; @return its time in ms, and the sections' lines into `lines`.
template <class Make>
double timed_pass(const Sections& s, Make make, std::vector<std::vector<PlaneId>>& lines) {
  const IntervalScope intervals;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < s.pairs.size(); ++k) {
    const std::optional<PlanePolygon> section = make(s.prims[s.pairs[k].first], s.pairs[k].second);
    lines[k].clear();
    if (section)
      for (const PlaneRef& t : section->lines) lines[k].push_back(t.id);
  }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> dirs;
  int rounds = 40;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 < argc && flag == "--homes") dirs.emplace_back(argv[++i]);
    else if (i + 1 < argc && flag == "--rounds") rounds = std::max(1, std::atoi(argv[++i]));
    else {
      std::fprintf(stderr, "usage: sections_bench [--homes DIR]... [--rounds N]\n");
      return 2;
    }
  }
  std::printf("%d rounds, one thread; ms per pass over every pair\n", rounds);
  std::printf("%-28s %7s %9s %9s %9s %9s %9s %7s %s\n", "home", "pairs", "crossing", "clip_min",
              "clip_med", "edges_min", "edges_med", "ratio", "same lines");
  for (const bench::NamedPlan& home : bench::read_homes(dirs)) {
    Sections s;
    make_sections(home.plan, s);
    std::size_t from_crossings = 0;
    {
      const IntervalScope intervals;
      for (const auto& [p, plane] : s.pairs)
        from_crossings += section_from_crossings(s.set, s.prims[p], plane).has_value();
    }
    const auto clipped = [&](const Primitive& prim, PlaneRef plane) {
      return section_by_clipping(s.set, s.box, prim, plane);
    };
    const auto from_edges = [&](const Primitive& prim, PlaneRef plane) {
      return section_of(s.set, s.box, prim, plane);
    };
    std::vector<std::vector<PlaneId>> clip_lines(s.pairs.size()), edge_lines(s.pairs.size());
    std::vector<double> clip_ms, edge_ms, ratios;
    for (int r = 0; r < rounds; ++r) {
      const double c = timed_pass(s, clipped, clip_lines),
                   e = timed_pass(s, from_edges, edge_lines);
      clip_ms.push_back(c), edge_ms.push_back(e), ratios.push_back(e / c);
    }
    bool same = true;
    for (std::size_t k = 0; k < s.pairs.size() && same; ++k) {
      std::sort(clip_lines[k].begin(), clip_lines[k].end());
      std::sort(edge_lines[k].begin(), edge_lines[k].end());
      same = clip_lines[k] == edge_lines[k];
    }
    std::printf("%-28s %7zu %8.1f%% %9.3f %9.3f %9.3f %9.3f %7.3f %s\n", home.name.c_str(),
                s.pairs.size(),
                100.0 * double(from_crossings) / double(std::max<std::size_t>(1, s.pairs.size())),
                *std::min_element(clip_ms.begin(), clip_ms.end()), median(clip_ms),
                *std::min_element(edge_ms.begin(), edge_ms.end()), median(edge_ms), median(ratios),
                same ? "yes" : "NO");
  }
  return 0;
}
