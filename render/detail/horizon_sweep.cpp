// SPDX-License-Identifier: GPL-3.0-or-later
// Clipping of section segments against piecewise-linear horizons, and their update.
#include "render/detail/horizon_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomcad::detail {
namespace {

constexpr double kUnsetUp = -std::numeric_limits<double>::infinity();
constexpr double kUnsetDown = std::numeric_limits<double>::infinity();

/// The part of [s0, s1] where a function linear in s, f0 at s0 and f1 at s1, is positive.
/// @return false if there is none (touching at a single point counts as none).
bool positive_part(double s0, double s1, double f0, double f1, double& a, double& b) {
  if (f0 <= 0.0 && f1 <= 0.0) return false;
  if (f0 > 0.0 && f1 > 0.0) {
    a = s0;
    b = s1;
    return true;
  }
  const double crossing = s0 + (s1 - s0) * (f0 / (f0 - f1));  // the linear intersection
  a = f0 > 0.0 ? s0 : crossing;
  b = f0 > 0.0 ? crossing : s1;
  return a < b;
}

ScreenPoint point_at(ScreenPoint p, ScreenPoint t, double s) {
  if (s == 0.0) return p;  // exact end points, so consecutive segments' pieces join exactly
  if (s == 1.0) return t;
  return {p.x + (t.x - p.x) * s, p.y + (t.y - p.y) * s};
}

}  // namespace

HorizonSweep::HorizonSweep(double width, int columns)
    : pitch_(width / columns),
      up_(static_cast<std::size_t>(columns) + 1, kUnsetUp),
      down_(static_cast<std::size_t>(columns) + 1, kUnsetDown),
      new_up_(up_),
      new_down_(down_) {}

void HorizonSweep::begin_section(HorizonSide unset_side) {
  unset_side_ = unset_side;
  open_ = false;
}

void HorizonSweep::end_section() {
  up_ = new_up_;
  down_ = new_down_;
  open_ = false;
}

std::size_t HorizonSweep::column_of(double x) const {
  const double k = std::floor(x / pitch_);
  const double last = static_cast<double>(up_.size() - 2);
  return static_cast<std::size_t>(std::clamp(k, 0.0, last));
}

void HorizonSweep::add_segment(ScreenPoint p, ScreenPoint t) {
  // Split the segment where it crosses columns: between two columns both it and the horizons
  // are straight, so each piece's crossings with them are exact linear intersections.
  std::vector<double> breaks{0.0};
  if (p.x != t.x) {
    const double lo = std::min(p.x, t.x);
    const double hi = std::max(p.x, t.x);
    for (double k = std::floor(lo / pitch_) + 1.0; k * pitch_ < hi; k += 1.0) {
      breaks.push_back((k * pitch_ - p.x) / (t.x - p.x));
    }
    if (p.x > t.x) std::reverse(breaks.begin() + 1, breaks.end());
  }
  breaks.push_back(1.0);

  std::vector<Piece> pieces;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    clip_interval(p, t, breaks[i], breaks[i + 1], pieces);
  }
  last_from_this_ = false;
  for (const Piece& piece : pieces) {
    keep_piece(point_at(p, t, piece.s0), point_at(p, t, piece.s1), piece.side);
  }
  raise_horizons(p, t);
}

void HorizonSweep::clip_interval(ScreenPoint p, ScreenPoint t, double s0, double s1,
                                 std::vector<Piece>& out) const {
  if (!(s0 < s1)) return;
  const double x0 = p.x + (t.x - p.x) * s0;
  const double x1 = p.x + (t.x - p.x) * s1;
  const std::size_t k = column_of(0.5 * (x0 + x1));
  const bool left_set = up_[k] != kUnsetUp;
  const bool right_set = up_[k + 1] != kUnsetUp;
  if (!left_set && !right_set) {
    out.push_back({s0, s1, unset_side_});  // nothing drawn behind here yet
    return;
  }
  const double base = static_cast<double>(k) * pitch_;
  // Where an earlier section ended inside this interval only one column is set; its value is
  // held flat across the interval (the ends of sections rarely fall on columns).
  const auto horizon = [&](const std::vector<double>& h, double x) {
    const double left = left_set ? h[k] : h[k + 1];
    const double right = right_set ? h[k + 1] : h[k];
    return left + (right - left) * ((x - base) / pitch_);
  };
  const double v0 = p.y + (t.y - p.y) * s0;
  const double v1 = p.y + (t.y - p.y) * s1;
  double a = 0.0;
  double b = 0.0;
  // Above the upper horizon and below the lower one are disjoint (upper >= lower), so the
  // visible part of the interval is at most these two pieces; keep them in order along s.
  Piece pieces[2];
  int count = 0;
  if (positive_part(s0, s1, v0 - horizon(up_, x0), v1 - horizon(up_, x1), a, b)) {
    pieces[count++] = {a, b, HorizonSide::upper};
  }
  if (positive_part(s0, s1, horizon(down_, x0) - v0, horizon(down_, x1) - v1, a, b)) {
    pieces[count++] = {a, b, HorizonSide::lower};
  }
  if (count == 2 && pieces[1].s0 < pieces[0].s0) std::swap(pieces[0], pieces[1]);
  out.insert(out.end(), pieces, pieces + count);
}

void HorizonSweep::raise_horizons(ScreenPoint p, ScreenPoint t) {
  const double lo = std::min(p.x, t.x);
  const double hi = std::max(p.x, t.x);
  const double last = static_cast<double>(up_.size() - 1);
  const double first_k = std::max(0.0, std::ceil(lo / pitch_));
  const double last_k = std::min(last, std::floor(hi / pitch_));
  for (double k = first_k; k <= last_k; k += 1.0) {
    const double x = k * pitch_;
    const auto i = static_cast<std::size_t>(k);
    // A vertical segment on a column raises it by both of its ends (seed: КОРРЕКЦИЯ).
    const double top =
        p.x == t.x ? std::max(p.y, t.y) : p.y + (t.y - p.y) * ((x - p.x) / (t.x - p.x));
    const double bottom = p.x == t.x ? std::min(p.y, t.y) : top;
    new_up_[i] = std::max(new_up_[i], top);
    new_down_[i] = std::min(new_down_[i], bottom);
  }
}

void HorizonSweep::keep_piece(ScreenPoint a, ScreenPoint b, HorizonSide side) {
  if (open_ && polylines_.back().side == side && polylines_.back().points.back() == a) {
    std::vector<ScreenPoint>& points = polylines_.back().points;
    // A piece continuing one of the same segment is collinear with it: move the end point
    // instead of adding one, so polylines hold only samples and horizon crossings.
    if (last_from_this_) {
      points.back() = b;
    } else {
      points.push_back(b);
    }
  } else {
    polylines_.push_back({side, {a, b}});
  }
  open_ = true;
  last_from_this_ = true;
}

}  // namespace roomcad::detail
