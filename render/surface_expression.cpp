// SPDX-License-Identifier: GPL-3.0-or-later
// Recursive-descent parser that emits a postfix program, and its stack evaluator.
#include "render/surface_expression.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

namespace roomcad {
namespace {

constexpr std::string_view kPrimaryExpected = "a number, variable or '('";

struct FunctionName {
  std::string_view name;
  ExprOp op;
};
constexpr std::array<FunctionName, 6> kFunctions{{{"abs", ExprOp::abs},
                                                  {"sqrt", ExprOp::sqrt},
                                                  {"exp", ExprOp::exp},
                                                  {"ln", ExprOp::ln},
                                                  {"sin", ExprOp::sin},
                                                  {"cos", ExprOp::cos}}};

bool is_identifier_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// Thrown inside the parser only; parse_surface_expression returns it as a parse_error.
struct ParseFailure {
  std::size_t column = 0;
  std::string message;
};

}  // namespace

/// Parser state plus the program under construction. A friend of SurfaceExpression.
class ExpressionCompiler {
 public:
  explicit ExpressionCompiler(std::string_view text) : text_(text) {}

  SurfaceExpression compile() {
    parse_sum();
    skip_spaces();
    if (pos_ < text_.size()) fail("an operator or the end of the expression");
    return std::move(out_);
  }

 private:
  void skip_spaces() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  /// Consumes `c` (after spaces) if it is next. @return whether it was.
  bool accept(char c) {
    skip_spaces();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  [[noreturn]] void fail(std::string_view expected) const {
    const std::size_t column = pos_ + 1;
    throw ParseFailure{
        column, "expected " + std::string(expected) + " at column " + std::to_string(column)};
  }
  /// Appends an op and tracks the stack depth: operands push one value, binary ops pop one.
  void emit(ExprOp op) {
    out_.ops_.push_back(op);
    if (op == ExprOp::constant || op == ExprOp::var_x || op == ExprOp::var_z) {
      ++depth_;
      out_.max_depth_ = std::max(out_.max_depth_, depth_);
    } else if (op == ExprOp::add || op == ExprOp::sub || op == ExprOp::mul || op == ExprOp::div ||
               op == ExprOp::pow) {
      --depth_;
    }
  }
  void emit_constant(double value) {
    out_.constants_.push_back(value);
    emit(ExprOp::constant);
  }

  /// Parses operand (op operand)* for left-associative operators of one precedence level.
  void parse_chain(void (ExpressionCompiler::*operand)(), char symbol_a, ExprOp op_a, char symbol_b,
                   ExprOp op_b) {
    (this->*operand)();
    for (;;) {
      ExprOp op;
      if (accept(symbol_a)) {
        op = op_a;
      } else if (accept(symbol_b)) {
        op = op_b;
      } else {
        return;
      }
      (this->*operand)();
      emit(op);
    }
  }
  void parse_sum() {
    parse_chain(&ExpressionCompiler::parse_product, '+', ExprOp::add, '-', ExprOp::sub);
  }
  void parse_product() {
    parse_chain(&ExpressionCompiler::parse_unary, '*', ExprOp::mul, '/', ExprOp::div);
  }
  void parse_unary() {
    // Every recursion passes here; a bound keeps hostile input ("((((...") off the C++ stack.
    constexpr std::size_t kMaxNesting = 256;
    if (++nesting_ > kMaxNesting) fail("less nesting (at most 256 levels)");
    if (accept('-')) {
      parse_unary();
      emit(ExprOp::neg);
    } else if (accept('+')) {
      parse_unary();
    } else {
      parse_power();
    }
    --nesting_;
  }
  void parse_power() {
    parse_primary();
    if (accept('^')) {
      parse_unary();  // right-associative: x^y^z = x^(y^z), and 2^-1 is allowed
      emit(ExprOp::pow);
    }
  }
  void parse_primary() {
    skip_spaces();
    if (accept('(')) {
      parse_sum();
      if (!accept(')')) fail("')'");
      return;
    }
    if (pos_ < text_.size() &&
        (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.')) {
      parse_number();
      return;
    }
    if (pos_ < text_.size() && is_identifier_char(text_[pos_])) {
      parse_name();
      return;
    }
    fail(kPrimaryExpected);
  }
  void parse_number() {
    double value = 0.0;
    const char* first = text_.data() + pos_;
    const auto [end, ec] = std::from_chars(first, text_.data() + text_.size(), value);
    if (ec != std::errc{} || !std::isfinite(value)) fail("a finite number");
    pos_ += static_cast<std::size_t>(end - first);
    emit_constant(value);
  }
  void parse_name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_identifier_char(text_[pos_])) ++pos_;
    const std::string_view name = text_.substr(start, pos_ - start);
    if (name == "x") return emit(ExprOp::var_x);
    if (name == "z") return emit(ExprOp::var_z);
    if (name == "pi") return emit_constant(std::numbers::pi);
    if (name == "e") return emit_constant(std::numbers::e);
    for (const FunctionName& f : kFunctions) {
      if (name != f.name) continue;
      if (!accept('(')) fail("'(' after " + std::string(name));
      parse_sum();
      if (!accept(')')) fail("')'");
      return emit(f.op);
    }
    pos_ = start;
    fail(std::string(kPrimaryExpected) + " (unknown name '" + std::string(name) +
         "'; known: x z pi e abs sqrt exp ln sin cos)");
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;
  std::size_t nesting_ = 0;
  SurfaceExpression out_;
};

namespace {

/// @return the value of a one-argument function, NaN outside its domain.
double apply_function(ExprOp op, double a) {
  switch (op) {
    case ExprOp::neg: return -a;
    case ExprOp::abs: return std::fabs(a);
    case ExprOp::sqrt: return a < 0.0 ? std::nan("") : std::sqrt(a);
    case ExprOp::exp: return std::exp(a);
    case ExprOp::ln: return a <= 0.0 ? std::nan("") : std::log(a);
    case ExprOp::sin: return std::sin(a);
    case ExprOp::cos: return std::cos(a);
    default: return std::nan("");
  }
}

/// @return a op b, NaN for division by zero and undefined powers.
double apply_operator(ExprOp op, double a, double b) {
  switch (op) {
    case ExprOp::add: return a + b;
    case ExprOp::sub: return a - b;
    case ExprOp::mul: return a * b;
    case ExprOp::div: return b == 0.0 ? std::nan("") : a / b;
    case ExprOp::pow: return std::pow(a, b);  // NaN for a negative base and a fractional power
    default: return std::nan("");
  }
}

}  // namespace

double SurfaceExpression::evaluate(double x, double z) const {
  // Expressions are short; a fixed buffer keeps evaluation allocation-free in the common case.
  constexpr std::size_t kInline = 32;
  std::array<double, kInline> inline_stack{};
  std::vector<double> heap_stack;
  double* stack = inline_stack.data();
  if (max_depth_ > kInline) {
    heap_stack.resize(max_depth_);
    stack = heap_stack.data();
  }
  std::size_t top = 0;
  std::size_t next_constant = 0;
  for (const ExprOp op : ops_) {
    switch (op) {
      case ExprOp::constant: stack[top++] = constants_[next_constant++]; break;
      case ExprOp::var_x: stack[top++] = x; break;
      case ExprOp::var_z: stack[top++] = z; break;
      case ExprOp::add:
      case ExprOp::sub:
      case ExprOp::mul:
      case ExprOp::div:
      case ExprOp::pow:
        --top;
        stack[top - 1] = apply_operator(op, stack[top - 1], stack[top]);
        break;
      default: stack[top - 1] = apply_function(op, stack[top - 1]); break;
    }
  }
  const double result = top == 1 ? stack[0] : std::nan("");
  return std::isfinite(result) ? result : std::nan("");
}

Result<SurfaceExpression> parse_surface_expression(std::string_view text) {
  try {
    return ExpressionCompiler(text).compile();
  } catch (const ParseFailure& failure) {
    return Error{Code::parse_error, failure.message, Location{"", "", 1, failure.column}};
  }
}

}  // namespace roomcad
