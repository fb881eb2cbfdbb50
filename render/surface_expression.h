// SPDX-License-Identifier: GPL-3.0-or-later
// Expressions y = f(x, z) for surface drawings: parsed once by recursive descent, then
// evaluated many times from a compact postfix program (no tree walking, no allocation).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace roomcad {

/// One instruction of a compiled expression (postfix order).
enum class ExprOp : unsigned char {
  constant,
  var_x,
  var_z,
  add,
  sub,
  mul,
  div,
  pow,
  neg,
  abs,
  sqrt,
  exp,
  ln,
  sin,
  cos,
};

/// A compiled expression of x and z. Evaluation never throws: a domain error (sqrt of a
/// negative, ln of a non-positive, division by zero, overflow) gives NaN, which callers treat
/// as "no sample here".
class SurfaceExpression {
 public:
  /// @param[in] x, z  the variables
  /// @return f(x, z), or NaN where f is undefined or not finite. O(program length).
  [[nodiscard]] double evaluate(double x, double z) const;

  /// @return the postfix program (for tests and debugging).
  [[nodiscard]] const std::vector<ExprOp>& program() const { return ops_; }

 private:
  friend class ExpressionCompiler;
  std::vector<ExprOp> ops_;
  std::vector<double> constants_;  ///< operands of the `constant` ops, in order
  std::size_t max_depth_ = 0;      ///< deepest evaluation stack the program needs
};

/// Parses and compiles an expression. Grammar (usual precedence; `^` is right-associative and
/// binds tighter than unary minus, so -x^2 = -(x^2) and 2^-1 = 0.5):
///   sum     := product (('+' | '-') product)*
///   product := unary (('*' | '/') unary)*
///   unary   := ('-' | '+') unary | power
///   power   := primary ('^' unary)?
///   primary := number | x | z | pi | e | func '(' sum ')' | '(' sum ')'
///   func    := abs | sqrt | exp | ln | sin | cos
/// Numbers are decimal with an optional exponent (1.5e-3). Spaces are ignored.
/// @return the compiled expression, or a parse_error whose location's `column` counts
///         characters from 1 (the end of the text is column size + 1) and whose message says
///         why ("expected a number, variable or '(' at column 3"). O(text length).
[[nodiscard]] Result<SurfaceExpression> parse_surface_expression(std::string_view text);

}  // namespace roomcad
