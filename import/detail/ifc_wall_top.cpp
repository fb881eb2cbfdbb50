// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/ifc_wall_top.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace roomcad::ifc {
namespace {

constexpr int kSamples = 64;         ///< stretches the result is checked in
constexpr double kShortest = 0.01;   ///< metres: a shorter stretch of top joins its neighbour
constexpr double kSame = 1e-6;       ///< metres: tops this close are the same top
constexpr double kLowestTop = 1e-3;  ///< metres: a wall clipped lower keeps this much

/// A plane's z over the centre line: z(u) = at_start + along * u, and its slope across.
struct TopLine {
  double at_start = 0.0;
  double along = 0.0;
  double across = 0.0;
  [[nodiscard]] double at(double u) const { return at_start + along * u; }
};

/// @return the clip's plane as a line over the centre line (metres), if it is not vertical.
std::optional<TopLine> line_of(const Clip& c, Point2 from, Point2 d, double k) {
  if (std::abs(c.removed.z) < 1e-9) return std::nullopt;
  const double px = k * c.point.x, py = k * c.point.y, pz = k * c.point.z;
  const double z0 = pz - (c.removed.x * (from.x - px) + c.removed.y * (from.y - py)) / c.removed.z;
  return TopLine{z0, -(c.removed.x * d.x + c.removed.y * d.y) / c.removed.z,
                 -(c.removed.x * -d.y + c.removed.y * d.x) / c.removed.z};
}

}  // namespace

WallTop clipped_top(Point2 from, Point2 to, double thickness, double bottom, double top,
                    const std::vector<Clip>& clips, double k) {
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  const Point2 d{(to.x - from.x) / length, (to.y - from.y) / length};
  const double middle_z = (bottom + top) / 2;
  auto at = [&](double u, double z) {
    return Vec{(from.x + d.x * u) / k, (from.y + d.y * u) / k, z / k};
  };
  // Line 0 is the body's own top; then one line per clip plane that is not vertical. The top
  // changes course only where a boundary begins or ends or two lines cross: between those
  // breaks it is one line, so the pieces are exact.
  std::vector<TopLine> lines{{top, 0.0, 0.0}};
  std::vector<const Clip*> owner{nullptr};
  std::vector<double> breaks{0.0, length};
  WallTop out;
  for (const Clip& c : clips) {
    if (const auto l = line_of(c, from, d, k)) {
      lines.push_back(*l), owner.push_back(&c);
      for (const double t : c.crossings(at(0.0, middle_z), at(length, middle_z)))
        breaks.push_back(t * length);
      continue;
    }
    // A vertical plane cuts an end (a mitre, a wall it meets), which the plan's joins make
    // again, unless it cuts the middle of the centre line.
    if (c.removes(at(length / 2, middle_z)))
      out.notes.push_back("a vertical clipping plane cuts through its middle; it is kept whole");
  }
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (std::size_t j = i + 1; j < lines.size(); ++j)
      if (lines[i].along != lines[j].along) {
        const double u =
            (lines[j].at_start - lines[i].at_start) / (lines[i].along - lines[j].along);
        if (u > 0.0 && u < length) breaks.push_back(u);
      }
  std::sort(breaks.begin(), breaks.end());
  // The top at u: the lowest applicable top line, and the highest applicable bottom.
  auto top_line = [&](double u) {
    std::size_t best = 0;
    for (std::size_t j = 1; j < lines.size(); ++j)
      if (owner[j]->removed.z > 0.0 && lines[j].at(u) < lines[best].at(u) &&
          owner[j]->bounds(at(u, lines[j].at(u))))
        best = j;
    return best;
  };
  auto bottom_at = [&](double u) {
    double z = bottom;
    for (std::size_t j = 1; j < lines.size(); ++j)
      if (owner[j]->removed.z < 0.0 && owner[j]->bounds(at(u, lines[j].at(u))))
        z = std::max(z, lines[j].at(u));
    return z;
  };
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double u0 = breaks[i], u1 = breaks[i + 1];
    if (u1 - u0 < kShortest) continue;
    const std::size_t line = top_line((u0 + u1) / 2);
    const TopLine& l = lines[line];
    if (!out.pieces.empty() && used.back() == line) {
      out.pieces.back().to = u1, out.pieces.back().top_to = l.at(u1);
    } else {
      out.pieces.push_back({u0, u1, l.at(u0), l.at(u1)});
      used.push_back(line);
    }
  }
  // Stretches shorter than kShortest went to their neighbours: close the gaps and measure.
  out.pieces.front().from = 0.0, out.pieces.back().to = length;
  for (std::size_t i = 0; i < out.pieces.size(); ++i) {
    TopPiece& p = out.pieces[i];
    const TopLine& l = lines[used[i]];
    if (i + 1 < out.pieces.size()) p.to = out.pieces[i + 1].from;
    p.top_from = l.at(p.from), p.top_to = l.at(p.to);
  }
  // Measured at evenly spaced points and in the middle of every stretch between breaks, each
  // against the piece it falls in (within a micrometre of a break, where the top may jump
  // or a boundary run along an end, not measured).
  std::vector<double> probes;
  for (int i = 0; i <= kSamples; ++i) probes.push_back(length * i / kSamples);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    probes.push_back((breaks[i] + breaks[i + 1]) / 2);
  double miss = 0.0, low = INFINITY, high = -INFINITY;
  for (const double u : probes) {
    const double b = bottom_at(u);
    low = std::min(low, b), high = std::max(high, b);
    if (std::any_of(breaks.begin(), breaks.end(), [u](double x) { return std::abs(x - u) < 1e-6; }))
      continue;
    std::size_t j = 0;
    while (j + 1 < out.pieces.size() && u >= out.pieces[j].to) ++j;
    miss = std::max(miss, std::abs(lines[used[j]].at(u) - lines[top_line(u)].at(u)));
  }
  out.bottom = low;
  if (high - low > kSame) {
    out.error = high - low;
    out.notes.push_back(fmt::format(
        "a clipping plane cuts its bottom unevenly; it stands on its lowest point, within "
        "{:.3f} m of the file's",
        high - low));
  }
  if (miss > kSame) {
    out.error = std::max(out.error, miss);
    out.notes.push_back(
        fmt::format("its clipped top has stretches shorter than {} m; they are imported with their "
                    "neighbours' tops, within {:.3f} m of the file's",
                    kShortest, miss));
  }
  double across = 0.0;
  for (const std::size_t j : used)
    across = std::max(across, std::abs(lines[j].across) * thickness / 2);
  if (across > kSame) {
    out.error = std::max(out.error, across);
    out.notes.push_back(fmt::format(
        "a clipping plane slopes across its thickness; its top is the plane's height over the "
        "centre line, within {:.3f} m of the file's at its faces",
        across));
  }
  for (TopPiece& p : out.pieces) {
    for (double* z : {&p.top_from, &p.top_to}) {
      if (*z - out.bottom >= kLowestTop) continue;
      out.error = std::max(out.error, out.bottom + kLowestTop - *z);
      out.notes.push_back("a clipping plane reaches its bottom; it keeps 1 mm of height there");
      *z = out.bottom + kLowestTop;
    }
  }
  return out;
}

std::optional<UprightWall> upright_wall(const Prism& p, double k, std::string& why) {
  const double depth =
      std::sqrt(p.sweep.x * p.sweep.x + p.sweep.y * p.sweep.y + p.sweep.z * p.sweep.z);
  if (!(depth > 0.0) || std::abs(p.sweep.z) > 1e-6 * depth || !p.holes.empty()) {
    why = "its body is not extruded vertically, nor horizontally from a profile with no holes";
    return std::nullopt;
  }
  const Point2 n{p.sweep.x / depth, p.sweep.y / depth};
  const Point2 h{-n.y, n.x};  // along the wall
  const Vec& o = p.outer.front();
  std::vector<Point2> profile;  // (metres along h, world z in metres)
  for (const Vec& v : p.outer) {
    if (std::abs((v.x - o.x) * n.x + (v.y - o.y) * n.y) > 1e-6 * depth) {
      why = "its body is extruded horizontally but not across its profile";
      return std::nullopt;
    }
    profile.push_back({k * ((v.x - o.x) * h.x + (v.y - o.y) * h.y), k * v.z});
  }
  // The profile's span over each abscissa: it must be one interval from the flat bottom.
  auto span = [&](double x) {
    std::vector<double> zs;
    for (std::size_t i = 0, j = profile.size() - 1; i < profile.size(); j = i++) {
      const Point2 a = profile[j], b = profile[i];
      if ((a.x <= x && x < b.x) || (b.x <= x && x < a.x))
        zs.push_back(a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x));
    }
    std::sort(zs.begin(), zs.end());
    return zs;
  };
  std::vector<double> xs;
  double bottom = INFINITY;
  for (const Point2& q : profile) xs.push_back(q.x), bottom = std::min(bottom, q.y);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end(), [](double a, double b) { return b - a < 1e-9; }),
           xs.end());
  std::vector<TopPiece> stretches;  // between consecutive corners' abscissae: one top edge
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double mid = (xs[i] + xs[i + 1]) / 2, quarter = (xs[i + 1] - xs[i]) / 4;
    const std::vector<double> zs = span(mid);
    const std::vector<double> further = span(mid + quarter);
    if (zs.size() != 2 || further.size() != 2 || std::abs(zs[0] - bottom) > 1e-6) {
      why =
          "its body is an upright profile that does not stand on a flat bottom with one top "
          "over each point";
      return std::nullopt;
    }
    const double slope = (further[1] - zs[1]) / quarter;
    stretches.push_back(
        {xs[i], xs[i + 1], zs[1] - slope * (mid - xs[i]), zs[1] + slope * (xs[i + 1] - mid)});
  }
  if (stretches.empty()) {
    why = "its upright profile has no width";
    return std::nullopt;
  }
  UprightWall out;
  const double x0 = xs.front(), x1 = xs.back();
  const Point2 centre{k * o.x + k * p.sweep.x / 2, k * o.y + k * p.sweep.y / 2};
  out.from = {centre.x + h.x * x0, centre.y + h.y * x0};
  out.to = {centre.x + h.x * x1, centre.y + h.y * x1};
  out.thickness = k * depth;
  out.top.bottom = bottom;
  // Stretches merged greedily while the top runs on without a step and every corner between
  // stays within kUprightTolerance of the merged chord.
  for (std::size_t a = 0; a < stretches.size();) {
    std::size_t b = a;
    double miss = 0.0;
    for (std::size_t c = a + 1; c < stretches.size(); ++c) {
      if (std::abs(stretches[c].top_from - stretches[c - 1].top_to) > kSame) break;
      const TopPiece chord{stretches[a].from, stretches[c].to, stretches[a].top_from,
                           stretches[c].top_to};
      // Distances square to the chord: steep stretches by the ends of an arch merge too.
      const double run = chord.to - chord.from, rise = chord.top_to - chord.top_from;
      double worst = 0.0;
      for (std::size_t q = a; q < c; ++q)
        worst = std::max(worst, std::abs((stretches[q].to - chord.from) * rise -
                                         (stretches[q].top_to - chord.top_from) * run) /
                                    std::hypot(run, rise));
      if (worst > kUprightTolerance) break;
      b = c, miss = worst;
    }
    out.top.pieces.push_back(
        {stretches[a].from - x0, stretches[b].to - x0, stretches[a].top_from, stretches[b].top_to});
    out.top.error = std::max(out.top.error, miss);
    a = b + 1;
  }
  for (TopPiece& piece : out.top.pieces) {
    for (double* z : {&piece.top_from, &piece.top_to}) {
      if (*z - bottom >= kLowestTop) continue;
      out.top.error = std::max(out.top.error, bottom + kLowestTop - *z);
      *z = bottom + kLowestTop;
    }
  }
  if (out.top.error > 0.0)
    out.top.notes.push_back(fmt::format(
        "it is an upright profile swept across (an elevation); it is imported as {} walls with "
        "sloped tops, within {:.3f} m of its outline",
        out.top.pieces.size(), out.top.error));
  return out;
}

}  // namespace roomcad::ifc
