// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input contract's values, checked by every driver once its input's structure is accepted,
// in the order of Constrained_fairing_defect: the coordinates, epsilon, the weights of the
// settings, the per-vertex bounds with the input positions in their boxes (Bound_parameters.h),
// and an area for the energy.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VALUE_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VALUE_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Bound_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The first defect of the values for the vertices of `part` (Fairing_part.h, or any class with
// its size(), number(), is_fixed() and for_each_vertex()), whose input points are X0 in the
// part's order; `triangles()` gives the triangles on them, in the same numbering, made only
// when every other value is accepted.
template <typename Part, typename Triangles, typename NamedParameters>
Input_error value_error(const Part& part, const Points& X0, const Triangles& triangles, double epsilon,
                        const Fairing_settings& settings, const NamedParameters& np)
{
  for(std::size_t k = 0; k < part.size(); ++k)
    if(!point(X0, k).allFinite())
      return non_finite_coordinate_error(part.number(k));
  if(!(std::isfinite(epsilon) && epsilon > 0))
    return invalid_epsilon_error(epsilon);
  if(!(std::isfinite(settings.fidelity_weight) && settings.fidelity_weight >= 0))
    return invalid_fidelity_weight_error(settings.fidelity_weight);
  if(!(std::isfinite(settings.sliver_barrier_weight) && settings.sliver_barrier_weight >= 0))
    return invalid_sliver_barrier_weight_error(settings.sliver_barrier_weight);
  if(Input_error error = Bound_parameters::check(part, X0, epsilon, np))
    return error;
  if(!Bending_energy::is_defined(triangles(), X0))
    return no_area_error();
  return {};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VALUE_CHECK_H
