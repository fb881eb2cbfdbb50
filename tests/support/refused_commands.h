// SPDX-License-Identifier: GPL-3.0-or-later
// Checking that command lines are refused as the command line promises (cli/command.h): exit
// status 2, the failure's code, and a message naming what was wrong.
#pragma once

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "support/run_command.h"

namespace roomcad::test {

/// A command line that must be refused: its arguments (after the verb), a piece of what it
/// must print, and the failure's code.
struct RefusedCase {
  std::vector<std::string> args;
  std::string message;
  Code code = Code::usage_error;
};

/// Runs `roomcad verb args...` for each case and expects it refused as the case says.
inline void expect_refused(const std::string& verb, std::span<const RefusedCase> cases) {
  for (const RefusedCase& c : cases) {
    std::vector<std::string> args = c.args;
    args.insert(args.begin(), verb);
    const CommandResult run = run_roomcad(args);
    EXPECT_EQ(run.status, 2) << c.message << "\n" << run.err;
    EXPECT_EQ(failure_code(run), c.code) << c.message << "\n" << run.err;
    EXPECT_NE((run.out + run.err).find(c.message), std::string::npos) << run.out << run.err;
  }
}

}  // namespace roomcad::test
