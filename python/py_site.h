// SPDX-License-Identifier: GPL-3.0-or-later
// Where a plan's site is, for the Python methods that need the sun (Plan.sun, Plan.render).
#pragma once

#include <string_view>

#include "plan/plan.h"

namespace roomcad::python {

/// @return the plan's site.location. @raise roomcad.Error usage_error "`what`: ..." saying
///         how to set it when the plan has none.
const GeoLocation& site_location(const Plan& plan, std::string_view what);

}  // namespace roomcad::python
