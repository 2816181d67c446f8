// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One variant of the default call (see default_call_variant.h); DEFAULT_CALL_VARIANT names it.

#include "default_call_variant.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

namespace benchmark {

Fairing_result DEFAULT_CALL_VARIANT(Mesh& mesh, double epsilon)
{
  return CGAL::Polygon_mesh_processing::constrained_fairing(mesh, epsilon);
}

} // namespace benchmark
