// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_OF_POINTS_H
#define CGAL_PMP_CONSTRAINED_FAIRING_OF_POINTS_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_driver.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Vertex_maps.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/read_named_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_set_input.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief fairs a point set while keeping every point within `epsilon` of its input position, or
within its box: the bending energy of the points is minimized under the bound, every point kept,
in its order.

The bending energy is that of each point's tangent fan: its `number_of_neighbors` nearest
neighbours projected into its tangent plane, their Delaunay triangulation, and the triangles around
the point there (the local triangulations of Sharp and Crane's Laplacian for point clouds, SGP
2020). Point \f$ i \f$'s row of the Laplacian \f$ L \f$ holds the fan's cotangent weights in the
plane; its mass \f$ M_i(X) \f$ is a third of its fan's area at the current points. The energy is
\f$ \sum_i |(L X)_i|^2 / M_i(X) \f$, the squared mean curvature integrated over the points' areas:
zero on planes, scale-invariant, so that the bound keeps curved surfaces from shrinking. As for
meshes, by default the points move along their normals (`tangential_motion(true)` lets them
slide too), and the accurate objective (`Constrained_fairing_objective::ACCURATE`) adds a pull
towards CGAL's jet smoothing of the points (`jet_smooth_point_set()`), projected into the bound.

The normals are the `normal_map`'s if given, else estimated as %CGAL does, on the same
neighbours: the jet fit of `jet_estimate_normals()`, oriented along a minimum spanning tree as
`mst_orient_normals()` orients (in a tenth of its memory); if the `normal_map` is writable, each
point's normal at the result is written to it, oriented as the input's. A point with no usable
neighbourhood (farther from its k-th neighbour than 4 times the median of that distance, or whose
neighbours leave no triangle around it) stays where it is, and is counted in
`Constrained_fairing_result::number_of_isolated_points`. A point on the border of its fan (a
scan's border) moves, but no bending is measured there.

The bound and the contract are those of `constrained_fairing()`, with the points numbered in
their order in `points`: the per-point maps are property maps whose key is a point's index
(`std::size_t`). A point set is rejected, and the points and normals left bit-identical, when
`number_of_neighbors` is under 3 (`Constrained_fairing_defect::INVALID_NUMBER_OF_NEIGHBORS`), a
coordinate is NaN or infinite, a given normal is zero, NaN or infinite
(`Constrained_fairing_defect::INVALID_NORMAL`), there are no more points than neighbours
(`Constrained_fairing_defect::TOO_FEW_POINTS`), two points coincide
(`Constrained_fairing_defect::DUPLICATE_POINTS`), the points are all on one line
(`Constrained_fairing_defect::NO_SURFACE`) or a method other than the default quasi-Newton method
is asked (`Constrained_fairing_defect::METHOD_NEEDS_MESH`), as on every other failure.

\tparam PointRange a model of `Range` whose iterator is a model of `ForwardIterator`, as in
        %CGAL's point set processing
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param points the point set, faired in place
\param epsilon the largest distance a point may move, and the cap of every other size
\param np the named parameters:
  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map associating points to the elements of `points`}
      \cgalParamType{a model of `ReadWritePropertyMap` whose value type is a `Point_3`}
      \cgalParamDefault{`CGAL::Identity_property_map<value_type>`}
    \cgalParamNEnd
    \cgalParamNBegin{normal_map}
      \cgalParamDescription{a property map associating normals to the elements of `points`: read,
        and written with the normals at the result if it is writable}
      \cgalParamType{a model of `ReadablePropertyMap` whose value type is a `Vector_3`}
      \cgalParamDefault{none: the normals are estimated}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_neighbors}
      \cgalParamDescription{the neighbours of each point, for its normal and its tangent fan}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{32}
    \cgalParamNEnd
    \cgalParamNBegin{others}
      \cgalParamDescription{those of `constrained_fairing()` that apply to points:
        `number_of_iterations`, `fairing_objective`, `fidelity_weight`, `tangential_motion`,
        `energy_decrease_threshold`, `initial_smoothing_steps`, `iteration_callback`,
        `deviation_bound`, `box_half_extents`, and the per-point maps `vertex_tolerance_map`,
        `vertex_is_constrained_map`, `vertex_box_half_extents_map`, `vertex_box_center_map`,
        `vertex_deviation_map` and `vertex_at_bound_map`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\return what the call did, as for `constrained_fairing()`
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Constrained_fairing_result constrained_fairing_of_points(PointRange& points, double epsilon,
                                                         const NamedParameters& np = parameters::default_values())
{
  namespace CF = internal::Constrained_fairing;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Value = typename std::iterator_traits<typename PointRange::iterator>::value_type;
  const auto point_map = choose_parameter(get_parameter(np, internal_np::point_map), Identity_property_map<Value>());
  const auto normal_map = choose_parameter(get_parameter(np, internal_np::normal_map), CF::No_map());
  const CF::Fairing_settings settings = CF::read_fairing_settings(np);
  CF::Point_set_input<PointRange, std::decay_t<decltype(point_map)>, std::decay_t<decltype(normal_map)> > input(
    points, point_map, normal_map, settings.number_of_neighbors, settings.method);
  const auto callback = CF::read_iteration_callback(np);
  return CF::run_fairing_driver(input, epsilon, settings, CF::read_vertex_maps(np), CF::Iteration_callback(callback),
                                CF::read_sparse_linear_solver(np));
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_OF_POINTS_H
