// SPDX-License-Identifier: GPL-3.0-or-later
// core/error.h and core/assert.h: Status and Result carry an Error (code, message, location);
// a broken RC_ASSERT is never run past.
#include "core/error.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/assert.h"
#include "support/invariant.h"

namespace roomcad {
namespace {

TEST(Error, ResultHoldsAValueOrItsError) {
  const Result<int> good = 7;
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(*good, 7);
  EXPECT_TRUE(good.status().ok());
  const Result<int> bad = Result<int>::failure(Code::invalid_value, "walls/3/thickness: -1",
                                               Location{"home.json", "/walls/3/thickness", 4, 18});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.code(), Code::invalid_value);
  EXPECT_EQ(bad.message(), "walls/3/thickness: -1");
  ASSERT_TRUE(bad.error().location.has_value());
  EXPECT_EQ(bad.error().location->line, 4u);
  EXPECT_EQ(bad.status().error(), bad.error());
}

TEST(Error, StatusIsSuccessOrAnError) {
  EXPECT_TRUE(Status::success().ok());
  const Status failed = Status::failure(Code::io_error, "cannot write out.obj");
  EXPECT_FALSE(failed);
  EXPECT_EQ(failed.code(), Code::io_error);
  std::ostringstream out;
  out << failed.error();
  EXPECT_NE(out.str().find("io_error"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("cannot write out.obj"), std::string::npos) << out.str();
}

TEST(Error, PreconditionErrorCarriesItsCode) {
  try {
    throw PreconditionError("build_model: wall 'w1' cannot be built", Code::not_buildable);
  } catch (const PreconditionError& e) {
    EXPECT_EQ(e.code(), Code::not_buildable);
    EXPECT_STREQ(e.what(), "build_model: wall 'w1' cannot be built");
  }
}

TEST(Assert, AHeldInvariantCostsNothingButItsTestOnce) {
  int evaluated = 0;
  RC_ASSERT(++evaluated == 1, "evaluated once");
  EXPECT_EQ(evaluated, 1);
}

TEST(Assert, ABrokenInvariantIsNeverRunPast) {
  const auto broken = [] { RC_ASSERT(1 + 1 == 3, "arithmetic holds"); };
  EXPECT_INVARIANT_BROKEN(broken());
}

}  // namespace
}  // namespace roomcad
