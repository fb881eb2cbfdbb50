// SPDX-License-Identifier: GPL-3.0-or-later
// Compiles: a module that links validation sees the public headers of validation and of what
// it links (plan, geometry). The control for the probes that must not compile.
#include "geometry/joins.h"
#include "plan/plan.h"
#include "validation/validate.h"

int layer_probe_control() { return 0; }
