// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/surface_expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace roomcad {
namespace {

SurfaceExpression compile(const std::string& text) {
  auto parsed = parse_surface_expression(text);
  if (!parsed) {
    ADD_FAILURE() << "'" << text << "': " << parsed.message();
    return {};
  }
  return std::move(parsed).value();
}

double eval(const std::string& text, double x = 0.0, double z = 0.0) {
  return compile(text).evaluate(x, z);
}

/// The parse error of a text that must not parse: its code is asserted here, and its column
/// (from its location) and message are returned for the test to check.
struct ExpressionError {
  std::size_t column = 0;
  std::string message;
};
ExpressionError error_of(const std::string& text) {
  auto parsed = parse_surface_expression(text);
  EXPECT_FALSE(parsed.ok()) << "'" << text << "' parsed";
  if (parsed.ok()) return {};
  EXPECT_EQ(parsed.code(), Code::parse_error);
  return {parsed.error().location->column, parsed.message()};
}

TEST(SurfaceExpression, Precedence) {
  EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("2 * 3 ^ 2"), 18.0);
  EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), -4.0);  // unary minus binds looser than ^
  EXPECT_DOUBLE_EQ(eval("x*x - z*z", 3.0, 2.0), 5.0);
  EXPECT_DOUBLE_EQ(eval("1 - -1"), 2.0);
}

TEST(SurfaceExpression, Associativity) {
  EXPECT_DOUBLE_EQ(eval("8 - 3 - 2"), 3.0);    // left
  EXPECT_DOUBLE_EQ(eval("8 / 4 / 2"), 1.0);    // left
  EXPECT_DOUBLE_EQ(eval("2 ^ 3 ^ 2"), 512.0);  // right: 2^(3^2)
  EXPECT_DOUBLE_EQ(eval("2 ^ -1"), 0.5);
}

TEST(SurfaceExpression, FunctionsAndConstants) {
  EXPECT_DOUBLE_EQ(eval("abs(x)", -2.5), 2.5);
  EXPECT_DOUBLE_EQ(eval("sqrt(x*x + z*z)", 3.0, 4.0), 5.0);
  EXPECT_DOUBLE_EQ(eval("exp(1)"), std::numbers::e);
  EXPECT_DOUBLE_EQ(eval("ln(e)"), 1.0);
  EXPECT_NEAR(eval("sin(pi/2) + cos(pi)"), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(eval("1.5e1 + .5"), 15.5);
  // Seed surface 10, the damped wave, at a = 0: cos(0) / (0 + 1) = 1.
  EXPECT_DOUBLE_EQ(eval("cos(sqrt(x*x+z*z))/(sqrt(x*x+z*z)+1)"), 1.0);
}

TEST(SurfaceExpression, DomainErrorsGiveNaN) {
  EXPECT_TRUE(std::isnan(eval("sqrt(x)", -1.0)));
  EXPECT_TRUE(std::isnan(eval("ln(x)", 0.0)));
  EXPECT_TRUE(std::isnan(eval("1/x", 0.0)));
  EXPECT_TRUE(std::isnan(eval("x ^ 0.5", -4.0)));
  EXPECT_TRUE(std::isnan(eval("exp(x)", 1000.0)));  // overflow is not a value either
  EXPECT_DOUBLE_EQ(eval("sqrt(x)", 4.0), 2.0);
}

TEST(SurfaceExpression, ErrorsNameColumnAndExpectation) {
  const ExpressionError dangling = error_of("x^");
  EXPECT_EQ(dangling.column, 3u);
  EXPECT_EQ(dangling.message, "expected a number, variable or '(' at column 3");
  EXPECT_EQ(error_of("").column, 1u);
  EXPECT_EQ(error_of("(x + 1").message, "expected ')' at column 7");
  EXPECT_EQ(error_of("x y").message,
            "expected an operator or the end of the expression at column 3");
  const ExpressionError unknown = error_of("2 * y");
  EXPECT_EQ(unknown.column, 5u);
  EXPECT_NE(unknown.message.find("unknown name 'y'"), std::string::npos) << unknown.message;
  EXPECT_EQ(error_of("sin x").message, "expected '(' after sin at column 5");
  EXPECT_EQ(error_of("1e999").column, 1u);
}

TEST(SurfaceExpression, DeepNestingIsAnErrorNotACrash) {
  const std::string deep(100000, '(');
  EXPECT_NE(error_of(deep).message.find("less nesting"), std::string::npos);
  const std::string ok = std::string(100, '(') + "x" + std::string(100, ')');
  EXPECT_DOUBLE_EQ(eval(ok, 7.0), 7.0);
}

}  // namespace
}  // namespace roomcad
