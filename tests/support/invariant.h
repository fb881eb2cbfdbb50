// SPDX-License-Identifier: GPL-3.0-or-later
// EXPECT_INVARIANT_BROKEN(statement): the statement breaks an RC_ASSERT (core/assert.h). Without
// NDEBUG (the sanitized build) that aborts, naming the invariant; with NDEBUG (Release) it
// throws PreconditionError with Code::internal.
#pragma once

#include <gtest/gtest.h>

#include "core/error.h"

#ifdef NDEBUG
#define EXPECT_INVARIANT_BROKEN(statement)                        \
  do {                                                            \
    try {                                                         \
      statement;                                                  \
      ADD_FAILURE() << "no invariant broken by: " #statement;     \
    } catch (const ::roomcad::PreconditionError& e) {             \
      EXPECT_EQ(e.code(), ::roomcad::Code::internal) << e.what(); \
    }                                                             \
  } while (false)
#else
#define EXPECT_INVARIANT_BROKEN(statement) EXPECT_DEATH(statement, "internal error")
#endif
