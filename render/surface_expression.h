// Expressions y = f(x, z) for surface drawings: parsed once by recursive descent, then
// evaluated many times from a compact postfix program (no tree walking, no allocation).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

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

/// Where and why parsing failed. `column` counts characters from 1; the end of the text is
/// column size + 1.
struct ExpressionError {
  std::size_t column = 0;
  std::string message;  ///< e.g. "expected a number, variable or '(' at column 3"
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
/// @return the compiled expression, or the error. O(text length).
[[nodiscard]] std::variant<SurfaceExpression, ExpressionError> parse_surface_expression(
    std::string_view text);

}  // namespace roomcad
