// SPDX-License-Identifier: GPL-3.0-or-later
// Radical: exact sums of rational multiples of products of square roots (see radical.h).
#include "exact/radical.h"

#include "core/assert.h"
#include "exact/precise_interval.h"

#include <CGAL/Interval_nt.h>
#include <mpfr.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace roomcad::exact {
namespace {

using Terms = std::vector<std::pair<std::uint64_t, mpq_class>>;

/// The radicands of the current scope; bit i of a mask stands for sqrt(radicands()[i]).
std::vector<mpq_class>& radicands() {
  thread_local std::vector<mpq_class> table;
  return table;
}

/// More roots than any plan predicate uses (at most two footprints of three walls each):
/// the subset search in register_root is 2^k.
constexpr std::size_t kMaxRoots = 16;

/// @return c * prod_{i in common} s_i: what sqrt factors shared by two multiplied terms give.
mpq_class with_squares(mpq_class c, std::uint64_t common) {
  for (std::size_t i = 0; common != 0; ++i, common >>= 1)
    if (common & 1) c *= radicands()[i];
  return c;
}

/// @return a + b_sign * b. Both are sorted by mask, so one merge pass (no map, no node
/// allocation: this is the inner loop of every exact predicate that reaches the roots).
Terms combine(const Terms& a, const Terms& b, int b_sign) {
  Terms out;
  out.reserve(a.size() + b.size());
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].first < b[j].first)) {
      out.push_back(a[i++]);
    } else if (i == a.size() || b[j].first < a[i].first) {
      out.emplace_back(b[j].first, b_sign < 0 ? mpq_class(-b[j].second) : b[j].second);
      ++j;
    } else {
      mpq_class c =
          b_sign < 0 ? mpq_class(a[i].second - b[j].second) : mpq_class(a[i].second + b[j].second);
      if (sgn(c) != 0) out.emplace_back(a[i].first, std::move(c));
      ++i, ++j;
    }
  }
  return out;
}

/// @return a * b: every pair of terms, then sorted by mask with equal masks summed.
Terms multiply(const Terms& a, const Terms& b) {
  Terms products;
  products.reserve(a.size() * b.size());
  for (const auto& [ma, ca] : a)
    for (const auto& [mb, cb] : b) products.emplace_back(ma ^ mb, with_squares(ca * cb, ma & mb));
  std::sort(products.begin(), products.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  Terms out;
  out.reserve(products.size());
  for (auto& [m, c] : products) {
    if (!out.empty() && out.back().first == m) out.back().second += c;
    else out.emplace_back(m, std::move(c));
  }
  std::erase_if(out, [](const auto& term) { return sgn(term.second) == 0; });
  return out;
}

/// Splits x = low + high * sqrt(s_k) on its highest root k. @return k, or -1 if x is rational.
int split(const Terms& x, Terms& low, Terms& high) {
  std::uint64_t all = 0;
  for (const auto& term : x) all |= term.first;
  if (all == 0) return -1;
  const int k = 63 - std::countl_zero(all);
  const std::uint64_t bit = std::uint64_t{1} << k;
  for (const auto& [m, c] : x) (m & bit ? high : low).emplace_back(m & ~bit, c);
  return k;
}

/// sign(a + b sqrt(s)) from sign(a), sign(b) and, when they differ, sign(a^2 - b^2 s).
int sign_of(const Terms& x) {
  Terms low, high;
  const int k = split(x, low, high);
  if (k < 0) return x.empty() ? 0 : sgn(x.front().second);
  const int sa = sign_of(low), sb = sign_of(high);
  if (sb == 0 || sa == sb) return sa == 0 ? sb : sa;
  if (sa == 0) return sb;
  const Terms s{{0, radicands()[static_cast<std::size_t>(k)]}};
  return sa * sign_of(combine(multiply(low, low), multiply(multiply(high, high), s), -1));
}

/// @return 1 / x. @pre x != 0. Multiplies by the conjugate over the highest root, whose norm
/// a^2 - b^2 s is non-zero because the roots are independent (see register_root).
Terms invert(const Terms& x) {
  Terms low, high;
  const int k = split(x, low, high);
  if (k < 0) {
    RC_ASSERT(!x.empty(), "a Radical is never divided by zero");
    return {{0, 1 / x.front().second}};
  }
  const std::uint64_t bit = std::uint64_t{1} << k;
  const Terms s{{0, radicands()[static_cast<std::size_t>(k)]}};
  Terms conjugate = low;
  for (const auto& [m, c] : high) conjugate.emplace_back(m | bit, -c);
  const Terms norm = combine(multiply(low, low), multiply(multiply(high, high), s), -1);
  return multiply(combine(conjugate, {}, 1), invert(norm));
}

bool is_square(const mpq_class& q) {
  return sgn(q) >= 0 && mpz_perfect_square_p(q.get_num_mpz_t()) != 0 &&
         mpz_perfect_square_p(q.get_den_mpz_t()) != 0;
}

mpq_class square_root(const mpq_class& q) {
  mpz_class n, d;
  mpz_sqrt(n.get_mpz_t(), q.get_num_mpz_t());
  mpz_sqrt(d.get_mpz_t(), q.get_den_mpz_t());
  return mpq_class(n, d);
}

/// Interval holding q: its double truncated toward zero, widened by an ulp each way.
CGAL::Interval_nt<false> enclose(const mpq_class& q) {
  const double d = q.get_d();
  return {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)};
}

}  // namespace

Radical::Scope::Scope() : entry_size_(radicands().size()) {}
Radical::Scope::~Scope() { radicands().resize(entry_size_); }

Radical::Radical(double x) {
  if (x != 0.0) terms_.emplace_back(0, mpq_class(x));
}

Radical Radical::from_terms(Terms terms) {
  Radical r;
  r.terms_ = std::move(terms);
  return r;
}

Radical scaled_root(const mpq_class& c, Radical::Mask m) { return Radical::from_terms({{m, c}}); }

Radical operator+(const Radical& a, const Radical& b) {
  return Radical::from_terms(combine(a.terms_, b.terms_, 1));
}
Radical operator-(const Radical& a, const Radical& b) {
  return Radical::from_terms(combine(a.terms_, b.terms_, -1));
}
Radical operator*(const Radical& a, const Radical& b) {
  return Radical::from_terms(multiply(a.terms_, b.terms_));
}
Radical operator/(const Radical& a, const Radical& b) {
  return Radical::from_terms(multiply(a.terms_, invert(b.terms_)));
}
Radical Radical::operator-() const { return from_terms(combine({}, terms_, -1)); }

int sign(const Radical& x) {
  // Most signs asked are far from zero: their interval tells, without the roots' recursion.
  if (x.terms_.size() > 1) {
    const auto [lo, hi] = to_interval(x);
    if (lo > 0) return 1;
    if (hi < 0) return -1;
  }
  return sign_of(x.terms_);
}

/// sqrt(s) = q / sqrt(prod P) = (q / prod P) * prod_{i in P} sqrt(s_i) when s * prod P = q^2
/// for a subset P of the registered radicands (P empty: s is a square); otherwise s is new.
Radical sqrt(const Radical& x) {
  if (x.terms_.empty()) return {};
  RC_ASSERT(
      x.terms_.size() == 1 && x.terms_.front().first == 0 && sgn(x.terms_.front().second) >= 0,
      "a Radical's square root is taken of a non-negative rational only");
  const mpq_class& s = x.terms_.front().second;
  std::vector<mpq_class>& table = radicands();
  for (Radical::Mask p = 0; p < (Radical::Mask{1} << table.size()); ++p) {
    const mpq_class product = with_squares(s, p);
    if (is_square(product)) return scaled_root(square_root(product) / with_squares(1, p), p);
  }
  RC_ASSERT(table.size() < kMaxRoots, "a predicate takes at most kMaxRoots distinct roots");
  table.push_back(s);
  return scaled_root(1, Radical::Mask{1} << (table.size() - 1));
}

std::pair<double, double> to_interval(const Radical& x) {
  using I = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> upward;
  I sum(0);
  for (const auto& [m, c] : x.terms_) {
    I term = enclose(c);
    for (std::size_t i = 0; (m >> i) != 0; ++i)
      if ((m >> i) & 1) term *= CGAL::sqrt(enclose(radicands()[i]));
    sum += term;
  }
  return {sum.inf(), sum.sup()};
}

std::optional<double> round_if_clear(const Radical& x) {
  if (x.terms_.empty()) return 0.0;
  constexpr mpfr_prec_t kBits = 192;
  mpfr_t lo, hi, tl, th, rl, rh;
  for (mpfr_ptr v : {lo, hi, tl, th, rl, rh}) mpfr_init2(v, kBits);
  mpfr_set_zero(lo, 1), mpfr_set_zero(hi, 1);
  for (const auto& [m, c] : x.terms_) {
    mpfr_set_q(tl, c.get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(th, c.get_mpq_t(), MPFR_RNDU);
    for (std::size_t i = 0; (m >> i) != 0; ++i) {
      if (!((m >> i) & 1)) continue;
      // [rl, rh] holds sqrt(s_i) >= 0: multiply [tl, th] by it, rounding outward.
      mpfr_set_q(rl, radicands()[i].get_mpq_t(), MPFR_RNDD);
      mpfr_set_q(rh, radicands()[i].get_mpq_t(), MPFR_RNDU);
      mpfr_sqrt(rl, rl, MPFR_RNDD);
      mpfr_sqrt(rh, rh, MPFR_RNDU);
      const bool low_negative = mpfr_sgn(tl) < 0, high_negative = mpfr_sgn(th) < 0;
      mpfr_mul(tl, tl, low_negative ? rh : rl, MPFR_RNDD);
      mpfr_mul(th, th, high_negative ? rl : rh, MPFR_RNDU);
    }
    mpfr_add(lo, lo, tl, MPFR_RNDD);
    mpfr_add(hi, hi, th, MPFR_RNDU);
  }
  const std::optional<double> nearest = nearest_double_if_clear(lo, hi);
  for (mpfr_ptr v : {lo, hi, tl, th, rl, rh}) mpfr_clear(v);
  return nearest;
}

namespace {

/// Doubles in order as integers (negative ones mirrored), so that a bisection can walk them.
std::int64_t order_key(double d) {
  const auto bits = std::bit_cast<std::int64_t>(d);
  return bits >= 0 ? bits : -(bits & std::numeric_limits<std::int64_t>::max());
}
double from_order_key(std::int64_t k) {
  return k >= 0 ? std::bit_cast<double>(k)
                : std::bit_cast<double>((-k) | std::numeric_limits<std::int64_t>::min());
}

}  // namespace

double round_to_nearest(const Radical& x) {
  if (const auto clear = round_if_clear(x)) return *clear;
  const auto [inf, sup] = to_interval(x);
  // Bisect for the largest double <= x between the bounds: at most 64 exact comparisons. The
  // bounds are infinite when a term of x overflows doubles though x does not (a mitre of walls
  // a denormal off straight divides by ~1e-323): then bisect over all finite doubles.
  constexpr double kMost = std::numeric_limits<double>::max();
  std::int64_t lo = order_key(std::max(inf, -kMost)), hi = order_key(std::min(sup, kMost));
  while (lo < hi) {
    // hi - lo may exceed int64 (from -max to max): halve it unsigned.
    const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    const std::int64_t mid = lo + static_cast<std::int64_t>((span + 1) / 2);
    if (Radical(from_order_key(mid)) <= x) lo = mid;
    else hi = mid - 1;
  }
  const double below = from_order_key(lo);
  if (Radical(below) == x || below == kMost) return below;
  const double above = from_order_key(lo + 1);
  return x > (Radical(below) + Radical(above)) / Radical(2) ? above : below;
}

}  // namespace roomcad::exact
