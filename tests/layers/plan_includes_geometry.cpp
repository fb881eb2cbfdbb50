// SPDX-License-Identifier: GPL-3.0-or-later
// Must not compile: the plan document sits below geometry.
#include "geometry/joins.h"
