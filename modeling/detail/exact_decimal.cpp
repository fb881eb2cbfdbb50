// exact_dot: the decimal-exact primitive behind modeling/transform2d.h. GMP integers hold
// decimal mantissas; the only rounding is the final strtod, which glibc rounds correctly.
#include <gmpxx.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "modeling/transform2d.h"

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

/// @return the double nearest to `d` (ties to even): strtod reads "<digits>e<exp>" exactly.
double round_to_double(const Decimal& d) {
  const std::string text = d.digits.get_str(10) + "e" + std::to_string(d.exp10);
  return std::strtod(text.c_str(), nullptr);
}

}  // namespace

double exact_dot(std::span<const double> a, std::span<const double> b) {
  std::vector<Decimal> terms;
  terms.reserve(a.size());
  double approximate = 0.0;  // the plain double result, used only when something is not finite
  bool finite = true;
  for (std::size_t i = 0; i < a.size(); ++i) {
    approximate += a[i] * b[i];
    if (!std::isfinite(a[i]) || !std::isfinite(b[i])) {
      finite = false;
      continue;
    }
    if (a[i] == 0.0 || b[i] == 0.0) continue;  // exact zero: no term (and no sign)
    const Decimal x = to_decimal(a[i]);
    const Decimal y = to_decimal(b[i]);
    terms.push_back({x.digits * y.digits, x.exp10 + y.exp10});
  }
  if (!finite) return approximate;
  if (terms.empty()) return 0.0;
  long lowest = terms.front().exp10;
  for (const Decimal& t : terms) lowest = std::min(lowest, t.exp10);
  Decimal sum{0, lowest};
  for (const Decimal& t : terms) {
    mpz_class scale;
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(t.exp10 - lowest));
    sum.digits += t.digits * scale;
  }
  return round_to_double(sum);
}

}  // namespace roomcad
