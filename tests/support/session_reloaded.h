// SPDX-License-Identifier: GPL-3.0-or-later
// test::reloaded(session): whether ViewSession::reload_if_changed reloaded the plan (a file that
// cannot be read or is no plan is an error: not reloaded either).
#pragma once

#include "view/view_session.h"

namespace roomcad::test {

inline bool reloaded(ViewSession& session) {
  const Result<bool> changed = session.reload_if_changed();
  return changed.ok() && *changed;
}

}  // namespace roomcad::test
