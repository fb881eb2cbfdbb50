// SPDX-License-Identifier: GPL-3.0-or-later
// Must not compile: validation judges the plan, not the solid; it does not link solid/.
#include "solid/build_model.h"
