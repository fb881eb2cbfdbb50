// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/written_number.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace roomcad::rules {
namespace {

/// 10^k exactly, for 0 <= k. Cost O(k / 22) exact products.
exact::Radical power_of_ten(int k) {
  exact::Radical out(1.0);
  for (; k > 22; k -= 22) out = out * exact::Radical(1e22);  // 1e22 is the last exact double
  double rest = 1.0;
  for (; k > 0; --k) rest *= 10.0;  // exact up to 1e22
  return out * exact::Radical(rest);
}

/// The shortest decimal that reads back to x, as an exact number. @pre x finite.
exact::Radical shortest_decimal(double x) {
  char text[64];
  const char* const end =
      std::to_chars(text, text + sizeof text, x, std::chars_format::scientific).ptr;
  // "d.ddddde+XX": at most 17 digits, split in two parts that doubles hold exactly.
  long long high = 0, low = 0;
  int digits = 0, low_digits = 0;
  const char* c = text;
  const bool negative = *c == '-';
  if (negative) ++c;
  for (; c != end && *c != 'e'; ++c) {
    if (*c == '.') continue;
    if (digits < 9) high = high * 10 + (*c - '0');
    else low = low * 10 + (*c - '0'), ++low_digits;
    ++digits;
  }
  int exponent = 0;
  if (c != end)
    std::from_chars(c + 1 + (c[1] == '+'), end, exponent);  // "e+05": from_chars takes no '+'
  exact::Radical mantissa = exact::Radical(static_cast<double>(high)) * power_of_ten(low_digits) +
                            exact::Radical(static_cast<double>(low));
  if (negative) mantissa = -mantissa;
  // value = mantissa * 10^(exponent - (digits - 1))
  const int scale = exponent - (digits - 1);
  return scale >= 0 ? mantissa * power_of_ten(scale) : mantissa / power_of_ten(-scale);
}

}  // namespace

bool is_binary_grid(double x) {
  const double scaled = std::ldexp(x, 30);
  return std::isfinite(scaled) && scaled == std::trunc(scaled);
}

WrittenApprox::WrittenApprox(double x)
    : v_(is_binary_grid(x) || !std::isfinite(x)
             ? exact::Approx(x)
             : exact::Approx(std::nextafter(x, -std::numeric_limits<double>::infinity()),
                             std::nextafter(x, std::numeric_limits<double>::infinity()))) {}

WrittenExact::WrittenExact(double x)
    : v_(is_binary_grid(x) ? exact::Radical(x) : shortest_decimal(x)) {}

}  // namespace roomcad::rules
