// SPDX-License-Identifier: GPL-3.0-or-later
#include "exact/precise_interval.h"

#include <cmath>
#include <limits>

namespace roomcad::exact {
namespace {

// Whether the interval holds 0.
bool holds_zero(mpfr_srcptr lo, mpfr_srcptr hi) { return mpfr_sgn(lo) <= 0 && mpfr_sgn(hi) >= 0; }

}  // namespace

void PreciseInterval::init() {
  mpfr_custom_init(lo_limbs_, kBits);
  mpfr_custom_init(hi_limbs_, kBits);
  mpfr_custom_init_set(lo_, MPFR_ZERO_KIND, 0, kBits, lo_limbs_);
  mpfr_custom_init_set(hi_, MPFR_ZERO_KIND, 0, kBits, hi_limbs_);
}

PreciseInterval::PreciseInterval() { init(); }

PreciseInterval PreciseInterval::corner_hull(const PreciseInterval& a, const PreciseInterval& b,
                                             Operation op) {
  // The four products (quotients) of the bounds, each rounded down (low) and up (high).
  mpfr_t low[4], high[4];
  mp_limb_t low_limbs[4][kLimbs], high_limbs[4][kLimbs];
  const mpfr_srcptr x[2] = {a.lo_, a.hi_}, y[2] = {b.lo_, b.hi_};
  for (int k = 0; k < 4; ++k) {
    mpfr_custom_init_set(low[k], MPFR_ZERO_KIND, 0, kBits, low_limbs[k]);
    mpfr_custom_init_set(high[k], MPFR_ZERO_KIND, 0, kBits, high_limbs[k]);
    op(low[k], x[k / 2], y[k % 2], MPFR_RNDD);
    op(high[k], x[k / 2], y[k % 2], MPFR_RNDU);
  }
  PreciseInterval r;
  mpfr_min(r.lo_, low[0], low[1], MPFR_RNDD);
  mpfr_min(r.lo_, r.lo_, low[2], MPFR_RNDD);
  mpfr_min(r.lo_, r.lo_, low[3], MPFR_RNDD);
  mpfr_max(r.hi_, high[0], high[1], MPFR_RNDU);
  mpfr_max(r.hi_, r.hi_, high[2], MPFR_RNDU);
  mpfr_max(r.hi_, r.hi_, high[3], MPFR_RNDU);
  return r;
}

PreciseInterval::PreciseInterval(double x) {
  init();
  mpfr_set_d(lo_, x, MPFR_RNDD);  // exact: 53 bits fit
  mpfr_set_d(hi_, x, MPFR_RNDU);
}

PreciseInterval::PreciseInterval(const PreciseInterval& other) {
  init();
  mpfr_set(lo_, other.lo_, MPFR_RNDD);
  mpfr_set(hi_, other.hi_, MPFR_RNDU);
}

PreciseInterval& PreciseInterval::operator=(const PreciseInterval& other) {
  mpfr_set(lo_, other.lo_, MPFR_RNDD);
  mpfr_set(hi_, other.hi_, MPFR_RNDU);
  return *this;
}

PreciseInterval PreciseInterval::between_corners(Operation op, mpfr_srcptr low_x, mpfr_srcptr low_y,
                                                 mpfr_srcptr high_x, mpfr_srcptr high_y) {
  PreciseInterval r;
  op(r.lo_, low_x, low_y, MPFR_RNDD);
  op(r.hi_, high_x, high_y, MPFR_RNDU);
  return r;
}

PreciseInterval operator+(const PreciseInterval& a, const PreciseInterval& b) {
  PreciseInterval r;
  mpfr_add(r.lo_, a.lo_, b.lo_, MPFR_RNDD);
  mpfr_add(r.hi_, a.hi_, b.hi_, MPFR_RNDU);
  return r;
}

PreciseInterval operator-(const PreciseInterval& a, const PreciseInterval& b) {
  PreciseInterval r;
  mpfr_sub(r.lo_, a.lo_, b.hi_, MPFR_RNDD);
  mpfr_sub(r.hi_, a.hi_, b.lo_, MPFR_RNDU);
  return r;
}

PreciseInterval PreciseInterval::operator-() const {
  PreciseInterval r;
  mpfr_neg(r.lo_, hi_, MPFR_RNDD);
  mpfr_neg(r.hi_, lo_, MPFR_RNDU);
  return r;
}

PreciseInterval operator*(const PreciseInterval& a, const PreciseInterval& b) {
  // The bounds' signs tell which corners bound the product: two products, not eight, unless
  // both intervals hold 0 inside.
  const int a_lo = mpfr_sgn(a.lo_), a_hi = mpfr_sgn(a.hi_), b_lo = mpfr_sgn(b.lo_),
            b_hi = mpfr_sgn(b.hi_);
  const auto corners = [](mpfr_srcptr low_x, mpfr_srcptr low_y, mpfr_srcptr high_x,
                          mpfr_srcptr high_y) {
    return PreciseInterval::between_corners(mpfr_mul, low_x, low_y, high_x, high_y);
  };
  if (a_lo >= 0) {
    if (b_lo >= 0) return corners(a.lo_, b.lo_, a.hi_, b.hi_);
    if (b_hi <= 0) return corners(a.hi_, b.lo_, a.lo_, b.hi_);
    return corners(a.hi_, b.lo_, a.hi_, b.hi_);
  }
  if (a_hi <= 0) {
    if (b_lo >= 0) return corners(a.lo_, b.hi_, a.hi_, b.lo_);
    if (b_hi <= 0) return corners(a.hi_, b.hi_, a.lo_, b.lo_);
    return corners(a.lo_, b.hi_, a.lo_, b.lo_);
  }
  if (b_lo >= 0) return corners(a.lo_, b.hi_, a.hi_, b.hi_);
  if (b_hi <= 0) return corners(a.hi_, b.lo_, a.lo_, b.lo_);
  return PreciseInterval::corner_hull(a, b, mpfr_mul);
}

PreciseInterval operator/(const PreciseInterval& a, const PreciseInterval& b) {
  if (holds_zero(b.lo_, b.hi_)) throw UndecidedComparison();
  // b holds one sign: the bounds' signs tell which two quotients bound the result.
  const auto quotients = [](mpfr_srcptr low_x, mpfr_srcptr low_y, mpfr_srcptr high_x,
                            mpfr_srcptr high_y) {
    return PreciseInterval::between_corners(mpfr_div, low_x, low_y, high_x, high_y);
  };
  const int a_lo = mpfr_sgn(a.lo_), a_hi = mpfr_sgn(a.hi_);
  if (mpfr_sgn(b.lo_) > 0) {
    if (a_lo >= 0) return quotients(a.lo_, b.hi_, a.hi_, b.lo_);
    if (a_hi <= 0) return quotients(a.lo_, b.lo_, a.hi_, b.hi_);
    return quotients(a.lo_, b.lo_, a.hi_, b.lo_);
  }
  if (a_lo >= 0) return quotients(a.hi_, b.hi_, a.lo_, b.lo_);
  if (a_hi <= 0) return quotients(a.hi_, b.lo_, a.lo_, b.hi_);
  return quotients(a.hi_, b.hi_, a.lo_, b.hi_);
}

PreciseInterval sqrt(const PreciseInterval& x) {
  if (mpfr_sgn(x.lo_) < 0) throw UndecidedComparison();
  PreciseInterval r;
  mpfr_sqrt(r.lo_, x.lo_, MPFR_RNDD);
  mpfr_sqrt(r.hi_, x.hi_, MPFR_RNDU);
  return r;
}

bool operator==(const PreciseInterval& a, const PreciseInterval& b) {
  if (mpfr_less_p(a.hi_, b.lo_) || mpfr_less_p(b.hi_, a.lo_)) return false;
  if (mpfr_equal_p(a.lo_, a.hi_) && mpfr_equal_p(b.lo_, b.hi_)) return true;  // one same number
  throw UndecidedComparison();
}

bool operator<(const PreciseInterval& a, const PreciseInterval& b) {
  if (mpfr_less_p(a.hi_, b.lo_)) return true;
  if (!mpfr_less_p(a.lo_, b.hi_)) return false;  // a.lo >= b.hi: every a at least every b
  throw UndecidedComparison();
}

std::optional<double> PreciseInterval::nearest_double() const {
  return nearest_double_if_clear(lo_, hi_);
}

std::optional<double> nearest_double_if_clear(mpfr_srcptr lo, mpfr_srcptr hi) {
  const double d = mpfr_get_d(lo, MPFR_RNDN);
  if (!std::isfinite(d) || std::abs(d) == std::numeric_limits<double>::max()) return std::nullopt;
  // The midpoints to the neighbours of d are 54-bit numbers: exact in one limb.
  mpfr_t below, above;
  mp_limb_t below_limbs[1], above_limbs[1];
  mpfr_custom_init_set(below, MPFR_ZERO_KIND, 0, GMP_NUMB_BITS, below_limbs);
  mpfr_custom_init_set(above, MPFR_ZERO_KIND, 0, GMP_NUMB_BITS, above_limbs);
  mpfr_set_d(below, std::nextafter(d, -INFINITY), MPFR_RNDN);
  mpfr_add_d(below, below, d, MPFR_RNDN);
  mpfr_div_2ui(below, below, 1, MPFR_RNDN);
  mpfr_set_d(above, std::nextafter(d, INFINITY), MPFR_RNDN);
  mpfr_add_d(above, above, d, MPFR_RNDN);
  mpfr_div_2ui(above, above, 1, MPFR_RNDN);
  if (mpfr_less_p(below, lo) && mpfr_less_p(hi, above))
    return d + 0.0;  // -0 as +0, as exact rounding gives
  return std::nullopt;
}

}  // namespace roomcad::exact
