// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_cut_out.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>

#include "plan/signed_area.h"

namespace roomcad::sh3d {
namespace {

constexpr int kMaxCurveChords = 256;  // per arc or curve: bounds the outline of any path

/// Reads the numbers and flags of an SVG path, skipping separators.
class PathReader {
 public:
  explicit PathReader(std::string_view text) : text_(text) {}

  void skip() {
    while (pos_ < text_.size() &&
           (std::isspace(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == ','))
      ++pos_;
  }
  [[nodiscard]] bool done() {
    skip();
    return pos_ >= text_.size();
  }
  /// @return whether a number (not a command letter) comes next.
  [[nodiscard]] bool number_next() {
    skip();
    if (pos_ >= text_.size()) return false;
    const char c = text_[pos_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
  }
  std::optional<char> command() {
    skip();
    if (pos_ >= text_.size() || !std::isalpha(static_cast<unsigned char>(text_[pos_])))
      return std::nullopt;
    return text_[pos_++];
  }
  std::optional<double> number() {
    skip();
    double value = 0;
    const char* begin = text_.data() + pos_;
    if (pos_ < text_.size() && text_[pos_] == '+') ++begin;
    const auto [end, ec] = std::from_chars(begin, text_.data() + text_.size(), value);
    if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
    pos_ = static_cast<std::size_t>(end - text_.data());
    return value;
  }
  /// An arc flag: one character 0 or 1 (SVG lets flags run together: "a1,1 0 11 1,0").
  std::optional<bool> flag() {
    skip();
    if (pos_ >= text_.size() || (text_[pos_] != '0' && text_[pos_] != '1')) return std::nullopt;
    return text_[pos_++] == '1';
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

/// @return `wanted` chords rounded up, within [1, kMaxCurveChords]. Clamped as a double before
/// the cast: a radius or a curve many orders above the tolerance makes the count infinite
/// (which no int holds: crash-cut-out-arc-radius-far-above-tolerance), a degenerate one NaN.
int chord_count(double wanted) {
  const double chords = std::ceil(wanted);
  if (!(chords > 1)) return 1;
  return chords < kMaxCurveChords ? static_cast<int>(chords) : kMaxCurveChords;
}

/// Chords for a turn of `sweep` radians on a radius of `radius` metres within `tolerance`.
int chords_for(double sweep, double radius, double tolerance) {
  if (!(radius > tolerance)) return 1;
  return chord_count(std::abs(sweep) / (2 * std::acos(1 - tolerance / radius)));
}

/// Appends the SVG elliptical arc from `p` to `q` (SVG 1.1, appendix F.6.5), without `p`.
void add_arc(Point2 p, double rx, double ry, double phi_deg, bool large, bool sweep, Point2 q,
             Point2 scale, double tolerance, Polygon& out) {
  rx = std::abs(rx), ry = std::abs(ry);
  if (rx == 0 || ry == 0 || p == q) {
    out.push_back(q);
    return;
  }
  const double phi = phi_deg * std::numbers::pi / 180;
  const double cs = std::cos(phi), sn = std::sin(phi);
  const double hx = (p.x - q.x) / 2, hy = (p.y - q.y) / 2;
  const double x1 = cs * hx + sn * hy, y1 = -sn * hx + cs * hy;
  const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
  if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
  const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  const double coef = (large != sweep ? 1 : -1) * std::sqrt(std::max(0.0, num / den));
  const double cx1 = coef * rx * y1 / ry, cy1 = -coef * ry * x1 / rx;
  const Point2 c{cs * cx1 - sn * cy1 + (p.x + q.x) / 2, sn * cx1 + cs * cy1 + (p.y + q.y) / 2};
  const double t1 = std::atan2((y1 - cy1) / ry, (x1 - cx1) / rx);
  double dt = std::atan2((-y1 - cy1) / ry, (-x1 - cx1) / rx) - t1;
  if (sweep && dt < 0) dt += 2 * std::numbers::pi;
  if (!sweep && dt > 0) dt -= 2 * std::numbers::pi;
  const double radius = std::max({rx * scale.x, ry * scale.y, rx * scale.y, ry * scale.x});
  const int n = chords_for(dt, radius, tolerance);
  for (int k = 1; k < n; ++k) {
    const double t = t1 + dt * k / n;
    out.push_back({c.x + rx * cs * std::cos(t) - ry * sn * std::sin(t),
                   c.y + rx * sn * std::cos(t) + ry * cs * std::sin(t)});
  }
  out.push_back(q);
}

/// Appends the Bezier curve through `control` (3 or 4 points, the first already in `out`).
void add_bezier(const std::vector<Point2>& control, Point2 scale, double tolerance, Polygon& out) {
  double reach = 0;  // the control polygon's length in metres bounds the curve's
  for (std::size_t k = 1; k < control.size(); ++k)
    reach += std::hypot((control[k].x - control[k - 1].x) * scale.x,
                        (control[k].y - control[k - 1].y) * scale.y);
  const int n = chord_count(std::sqrt(reach / tolerance));
  for (int k = 1; k <= n; ++k) {
    std::vector<Point2> p = control;  // de Casteljau
    const double t = static_cast<double>(k) / n;
    for (std::size_t level = p.size() - 1; level > 0; --level)
      for (std::size_t i = 0; i < level; ++i)
        p[i] = {p[i].x + t * (p[i + 1].x - p[i].x), p[i].y + t * (p[i + 1].y - p[i].y)};
    out.push_back(p[0]);
  }
}

/// Reads `count` coordinates after a command letter, relative to `at` if `relative`.
std::optional<std::vector<Point2>> read_points(PathReader& r, int count, bool relative, Point2 at) {
  std::vector<Point2> points;
  for (int k = 0; k < count; ++k) {
    const std::optional<double> x = r.number();
    const std::optional<double> y = r.number();
    if (!x || !y) return std::nullopt;
    points.push_back(relative ? Point2{at.x + *x, at.y + *y} : Point2{*x, *y});
  }
  return points;
}

/// One drawing command with its arguments, appending to `out`. @return false if malformed.
bool draw(char cmd, PathReader& r, Point2 scale, double tolerance, Polygon& out) {
  const bool rel = std::islower(static_cast<unsigned char>(cmd));
  const Point2 at = out.back();
  switch (std::tolower(static_cast<unsigned char>(cmd))) {
    case 'l': {
      const auto p = read_points(r, 1, rel, at);
      if (p) out.push_back((*p)[0]);
      return p.has_value();
    }
    case 'h':
    case 'v': {
      const std::optional<double> d = r.number();
      if (!d) return false;
      const bool h = std::tolower(static_cast<unsigned char>(cmd)) == 'h';
      out.push_back(h ? Point2{rel ? at.x + *d : *d, at.y} : Point2{at.x, rel ? at.y + *d : *d});
      return true;
    }
    case 'a': {
      const auto rx = r.number(), ry = r.number(), phi = r.number();
      const auto large = r.flag(), sweep = r.flag();
      const auto q = read_points(r, 1, rel, at);
      if (!rx || !ry || !phi || !large || !sweep || !q) return false;
      add_arc(at, *rx, *ry, *phi, *large, *sweep, (*q)[0], scale, tolerance, out);
      return true;
    }
    case 'c':
    case 'q': {
      const int n = std::tolower(static_cast<unsigned char>(cmd)) == 'c' ? 3 : 2;
      const auto p = read_points(r, n, rel, at);
      if (!p) return false;
      std::vector<Point2> control{at};
      control.insert(control.end(), p->begin(), p->end());
      add_bezier(control, scale, tolerance, out);
      return true;
    }
    default: return false;
  }
}

/// The points of the path's first sub-path, in path coordinates (y down).
std::optional<Polygon> trace(std::string_view path, Point2 scale, double tolerance) {
  PathReader r(path);
  const std::optional<char> first = r.command();
  if (!first || std::tolower(static_cast<unsigned char>(*first)) != 'm') return std::nullopt;
  const auto start = read_points(r, 1, false, {0, 0});
  if (!start) return std::nullopt;
  Polygon out{(*start)[0]};
  char cmd = *first == 'm' ? 'l' : 'L';  // pairs after a moveto are linetos
  while (!r.done()) {
    if (!r.number_next()) {
      const std::optional<char> next = r.command();
      if (!next) return std::nullopt;
      if (*next == 'z' || *next == 'Z') break;
      cmd = *next;
    }
    if (!draw(cmd, r, scale, tolerance, out)) return std::nullopt;
  }
  return out;
}

}  // namespace

std::optional<Polygon> parse_cut_out(std::string_view path, double width, double height,
                                     double tolerance) {
  std::optional<Polygon> traced = trace(path, {width, height}, tolerance);
  if (!traced) return std::nullopt;
  Polygon polygon;
  for (const Point2& p : *traced) {
    const Point2 up{p.x, 1 - p.y};
    if (polygon.empty() || !(polygon.back() == up)) polygon.push_back(up);
  }
  while (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
  const double area = signed_area(polygon);
  if (polygon.size() < 3 || !(std::abs(area) > 1e-9)) return std::nullopt;
  if (area < 0) std::ranges::reverse(polygon);
  return polygon;
}

Polygon clip_half_plane(const Polygon& polygon, double a, double b, double c) {
  Polygon out;
  const auto excess = [&](Point2 p) { return a * p.x + b * p.y - c; };
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    const double ep = excess(p), eq = excess(q);
    if (ep <= 0) out.push_back(p);
    if ((ep < 0 && eq > 0) || (ep > 0 && eq < 0)) {
      const double t = ep / (ep - eq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

}  // namespace roomcad::sh3d
