// SPDX-License-Identifier: GPL-3.0-or-later
// Must not compile, though solid is linked: solid/detail/ is private to solid.
#include "solid/detail/general_path/plane_faces.h"
