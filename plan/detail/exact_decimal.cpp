// SPDX-License-Identifier: GPL-3.0-or-later
// The decimal-exact primitives behind plan/transform2d.h (exact_dot, apply_exactly). GMP
// integers hold decimal mantissas; the only rounding is the final strtod, which glibc rounds
// correctly.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

#include "plan/transform2d.h"

namespace roomcad {
namespace {

/// digits * 10^exp10, exactly.
struct Decimal {
  mpz_class digits;
  long exp10 = 0;
};

/// @return the shortest decimal that reads back to `x` (std::to_chars' shortest form,
///         e.g. "1.1", "-2.5e-07", "1e+22"), as an exact Decimal. @pre std::isfinite(x).
Decimal to_decimal(double x) {
  char text[64];
  char* const end = std::to_chars(text, text + sizeof text - 1, x).ptr;
  *end = '\0';  // strtol below reads the exponent up to here
  std::string mantissa;
  long exp10 = 0;
  bool after_point = false;
  for (const char* c = text; c != end; ++c) {
    if (*c == 'e') {
      exp10 += std::strtol(c + 1, nullptr, 10);
      break;
    }
    if (*c == '.') {
      after_point = true;
    } else if (*c != '-') {
      mantissa += *c;
      if (after_point) --exp10;
    }
  }
  Decimal d{mpz_class(mantissa, 10), exp10};
  if (std::signbit(x)) d.digits = -d.digits;
  return d;
}

Decimal multiply(const Decimal& a, const Decimal& b) {
  return {a.digits * b.digits, a.exp10 + b.exp10};
}

/// @return a + b, exactly (the mantissa with the larger exponent is scaled down to the other).
Decimal add(const Decimal& a, const Decimal& b) {
  const Decimal& low = a.exp10 <= b.exp10 ? a : b;
  const Decimal& high = a.exp10 <= b.exp10 ? b : a;
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(high.exp10 - low.exp10));
  return {low.digits + high.digits * scale, low.exp10};
}

/// @return the double nearest to `d` (ties to even): strtod reads "<digits>e<exp>" exactly.
double round_to_double(const Decimal& d) {
  if (d.digits == 0) return 0.0;
  const std::string text = d.digits.get_str(10) + "e" + std::to_string(d.exp10);
  return std::strtod(text.c_str(), nullptr);
}

bool is_finite(const Transform2d& t) {
  return std::all_of(t.m.begin(), t.m.end(), [](const auto& row) {
    return std::all_of(row.begin(), row.end(), [](double x) { return std::isfinite(x); });
  });
}

}  // namespace

double exact_dot(std::span<const double> a, std::span<const double> b) {
  const auto finite = [](double x) { return std::isfinite(x); };
  if (!std::all_of(a.begin(), a.end(), finite) || !std::all_of(b.begin(), b.end(), finite)) {
    double plain = 0.0;  // NaN and infinities propagate as in double arithmetic
    for (std::size_t i = 0; i < a.size(); ++i) plain += a[i] * b[i];
    return plain;
  }
  Decimal sum{0, 0};
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == 0.0 || b[i] == 0.0) continue;  // exact zero: no term
    sum = add(sum, multiply(to_decimal(a[i]), to_decimal(b[i])));
  }
  return round_to_double(sum);
}

Point2 apply_exactly(std::span<const Transform2d> chain, Point2 p) {
  const bool finite = std::isfinite(p.x) && std::isfinite(p.y) &&
                      std::all_of(chain.begin(), chain.end(), is_finite);
  if (!finite) {  // NaN and infinities propagate as in double arithmetic
    for (const Transform2d& t : chain) p = apply(t, p);
    return p;
  }
  std::array<Decimal, 3> row{to_decimal(p.x), to_decimal(p.y), Decimal{1, 0}};
  for (const Transform2d& t : chain) {
    std::array<Decimal, 3> next{Decimal{0, 0}, Decimal{0, 0}, Decimal{0, 0}};
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        if (t.m[i][j] != 0.0) next[j] = add(next[j], multiply(row[i], to_decimal(t.m[i][j])));
    row = std::move(next);
  }
  return {round_to_double(row[0]), round_to_double(row[1])};
}

}  // namespace roomcad
