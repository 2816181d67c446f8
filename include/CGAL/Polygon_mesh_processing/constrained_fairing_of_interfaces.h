// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_OF_INTERFACES_H
#define CGAL_PMP_CONSTRAINED_FAIRING_OF_INTERFACES_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_driver.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Interface_input.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/read_named_parameters.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief fairs a multi-label surface, all its interfaces at once, while keeping every point within
`epsilon` of its input position, or within its box.

The surface is a triangle soup whose triangles each separate two labels, as
`label_surface_nets()` makes it from a label map: `face_labels[f]` are the labels on the two
sides of triangle `f`, its normal pointing from the first's region into the second's. The
interfaces (the triangles of one pair of labels) share their points, so the labels' surfaces
(`label_surface()`) still fit together exactly, with no gap and no overlap, after the call.

The objective is that of `constrained_fairing()`: the bending energy, here inside each interface
(its hinges are the edges of exactly two of its triangles), with the barrier against slivers and,
with `Constrained_fairing_objective::ACCURATE`, the fidelity term. A barrier against folds is
added: a hinge whose two normals are more than 60 degrees apart adds 3 times
\f$ (\cos 60^\circ - \cos\theta)^2 \f$, \f$ \theta \f$ the angle between them, which keeps
triangles from turning over against their neighbours where the junction lines and the volumes pull
(`sliver_barrier_weight(0)` removes both barriers). The junction lines, where three
labels or more meet along an edge, are faired as curves: their second differences, relative to
their segments' length, are added to the objective, so that a line keeps its crease and is not
rounded off. The volume that each label's surface encloses, where that surface is closed, is held
at its input value to within that value's uncertainty (a penalty on the surface's mean offset
beyond it): the voxels' count times a voxel's volume for surface nets, which the bending energy
alone would let grow on thin regions. A point
that ends a junction line or where lines branch, and a point where four labels or more meet, does
not move.

After the descent, the points of a triangle that passes through another, where it crossed none in
the input, those of a triangle whose smallest angle is under both 5 degrees and its own in the
input, and those of a triangle turned over against its neighbours (its normal opposite the sum of
theirs) that was not in the input, with its neighbours' points, are pulled back towards their
input positions, halfway at each of a point's first six pulls and all the way at its seventh: two
triangles of the faired soup cross only where one of them crossed a triangle in the input, no
triangle's smallest angle is under both 5 degrees and its input's, and a triangle is turned over
only where it was in the input (with `sliver_barrier_weight(0)`, the crossings alone).

The bound and the contract are those of `constrained_fairing()`, with the points numbered in
`points`: the per-point maps are property maps whose key is a point's index (`std::size_t`);
`box_half_extents` (half the voxel spacing for surface nets) gives every point the box around
its input position. A soup with a point index out of range or repeated in a triangle, a triangle
with the same label on both sides (`Constrained_fairing_defect::INVALID_FACE`), or two triangles
of one interface running through their shared edge the same way
(`Constrained_fairing_defect::INCONSISTENT_ORIENTATION`) is rejected, and `points` left
bit-identical, as on every other failure.

\tparam PointRange a random access container of points, with `x()`, `y()`, `z()` and a
        constructor from three `double`
\tparam TriangleRange a random access range of arrays of three point indices (any integer type)
\tparam LabelPairRange a random access range of arrays of two labels (any integer type), one per
        triangle
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param points the points of the surface, faired in place
\param triangles the triangles
\param face_labels the labels on the two sides of each triangle
\param epsilon the largest distance a point may move, and the cap of every other size
\param np the named parameters of `constrained_fairing()` that apply to a soup:
       `number_of_iterations`, `fairing_method`, `fairing_objective`, `fidelity_weight`,
       `sliver_barrier_weight`, `tangential_motion`, `energy_decrease_threshold`,
       `conjugate_gradient_iterations`, `initial_smoothing_steps`, `sparse_linear_solver`,
       `iteration_callback`, `deviation_bound`, `box_half_extents`, and the per-point maps
       `vertex_tolerance_map`, `vertex_is_constrained_map`, `vertex_box_half_extents_map`,
       `vertex_box_center_map`, `vertex_deviation_map`, `vertex_at_bound_map`. `feature_angle`
       is rejected (`Constrained_fairing_defect::INVALID_FEATURE_ANGLE`): a soup's curves are
       its junction lines, and no creases are detected

\return a `Constrained_fairing_result`, whose fixed vertices include the points that stay where
        junction lines end, branch, or four labels meet
*/
template <typename PointRange, typename TriangleRange, typename LabelPairRange,
          typename NamedParameters = parameters::Default_named_parameters>
Constrained_fairing_result constrained_fairing_of_interfaces(PointRange& points, const TriangleRange& triangles,
                                                             const LabelPairRange& face_labels, double epsilon,
                                                             const NamedParameters& np = parameters::default_values())
{
  namespace CF = internal::Constrained_fairing;
  CF::Interface_input<PointRange, TriangleRange, LabelPairRange> input(points, triangles, face_labels);
  const auto callback = CF::read_iteration_callback(np);
  return CF::run_fairing_driver(input, epsilon, CF::read_fairing_settings(np), CF::read_vertex_maps(np),
                                CF::Iteration_callback(callback), CF::read_sparse_linear_solver(np));
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_OF_INTERFACES_H
