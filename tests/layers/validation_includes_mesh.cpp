// SPDX-License-Identifier: GPL-3.0-or-later
// Must not compile: validation does not link mesh/ (OpenMesh).
#include "mesh/solid_mesh.h"
