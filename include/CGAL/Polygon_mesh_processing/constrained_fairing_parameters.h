// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_PARAMETERS_H
#define CGAL_PMP_CONSTRAINED_FAIRING_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Polygon_mesh_processing {

/// \ingroup PkgConstrainedFairingRef
/// The shape of the set in which each vertex may move around its input position `p0`.
enum class Deviation_bound
{
  /// `|p - p0| <= epsilon`, Euclidean distance: what "within epsilon" means. The default.
  BALL,
  /// `|p_i - p0_i| <= epsilon` for each coordinate `i`: the cube of side `2 epsilon` of
  /// Hildebrandt and Polthier's paper. A vertex may then move up to `sqrt(3) epsilon`.
  BOX
};

/// \ingroup PkgConstrainedFairingRef
/// The optimization method of `constrained_fairing()`.
enum class Constrained_fairing_method
{
  /// A projected limited-memory BFGS (quasi-Newton) method: the descent direction comes from the
  /// last few steps and gradient changes, restricted to the constraints that bind; no linear
  /// system is solved. The default: it reaches the paper's methods' lowest energy of 500
  /// iterations 57 to 145 times sooner in our measurements, and goes lower.
  QUASI_NEWTON,
  /// The active set Newton method of Hildebrandt and Polthier: a Cauchy step along the projected
  /// gradient, then a Newton step on the free variables, preconditioned by a thin plate
  /// Hessian factorized once.
  ACTIVE_SET_NEWTON,
  /// Cauchy steps only: the explicit projected gradient descent that the paper compares
  /// against. Cheaper per iteration, far more iterations on irregular meshes.
  PROJECTED_GRADIENT
};

/// \ingroup PkgConstrainedFairingRef
/// What `constrained_fairing()` minimizes inside the bound.
enum class Constrained_fairing_objective
{
  /// The bending energy of Hildebrandt and Polthier: the fairest surface within the bound. The
  /// default. Detail smaller than the bound is flattened, so the result may lie farther from
  /// the true surface than the noise was.
  FAIREST,
  /// The bending energy plus a fidelity term, `mu / n * sum_i |p_i - a_i|^2 / t_i^2`
  /// (over the `n` vertices that may move, `t_i` the tolerance of vertex `i`,
  /// `mu` the `fidelity_weight`), `a_i` the vertex's position in a denoised copy of the input
  /// (Taubin steps, bilateral filtering of the face normals and a vertex fit to them, each step
  /// followed by a move back into the bound): the filter keeps the detail larger than the
  /// noise, and the bending energy removes what it leaves. Closer to the true surface of a
  /// noisy scan, a little less fair; the bound holds as with `FAIREST`.
  ACCURATE
};

namespace internal {
namespace Constrained_fairing {

enum deviation_bound_t { deviation_bound };
enum fairing_method_t { fairing_method };
enum energy_decrease_threshold_t { energy_decrease_threshold };
enum conjugate_gradient_iterations_t { conjugate_gradient_iterations };
enum iteration_callback_t { iteration_callback };
enum initial_smoothing_steps_t { initial_smoothing_steps };
enum vertex_tolerance_map_t { vertex_tolerance_map };
enum box_half_extents_t { box_half_extents };
enum vertex_box_half_extents_map_t { vertex_box_half_extents_map };
enum vertex_box_center_map_t { vertex_box_center_map };
enum vertex_deviation_map_t { vertex_deviation_map };
enum vertex_at_bound_map_t { vertex_at_bound_map };
enum fairing_objective_t { fairing_objective };
enum fidelity_weight_t { fidelity_weight };
enum sliver_barrier_weight_t { sliver_barrier_weight };
enum tangential_motion_t { tangential_motion };
enum feature_angle_t { feature_angle };
enum number_of_neighbors_t { number_of_neighbors };

} // namespace Constrained_fairing
} // namespace internal

/// \ingroup PkgConstrainedFairingRef
/// The named parameters of `constrained_fairing()` that %CGAL does not have. Each function
/// starts a pack that chains %CGAL's own parameters as members, for example
/// `deviation_bound(Deviation_bound::BOX).number_of_iterations(50)`; its two-argument
/// overload appends to an existing pack, for example
/// `deviation_bound(Deviation_bound::BOX, CGAL::parameters::number_of_iterations(50))`.
namespace constrained_fairing_parameters {

#define CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(NAME)                                          \
  template <typename T>                                                                       \
  Named_function_parameters<T, internal::Constrained_fairing::NAME##_t>                       \
  NAME(const T& value)                                                                        \
  {                                                                                           \
    return Named_function_parameters<T, internal::Constrained_fairing::NAME##_t>(value);      \
  }                                                                                           \
  template <typename T, typename NP_T, typename NP_Tag, typename NP_Base>                     \
  Named_function_parameters<T, internal::Constrained_fairing::NAME##_t,                       \
                            Named_function_parameters<NP_T, NP_Tag, NP_Base> >                \
  NAME(const T& value, const Named_function_parameters<NP_T, NP_Tag, NP_Base>& base)          \
  {                                                                                           \
    return Named_function_parameters<T, internal::Constrained_fairing::NAME##_t,              \
                                     Named_function_parameters<NP_T, NP_Tag, NP_Base> >(      \
      value, base);                                                                           \
  }

/// the shape of the bound, a `Deviation_bound`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(deviation_bound)
/// the optimization method, a `Constrained_fairing_method`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(fairing_method)
/// the stopping threshold on the relative energy decrease, a `double`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(energy_decrease_threshold)
/// the largest number of conjugate gradient iterations per Newton step, a `std::size_t`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(conjugate_gradient_iterations)
/// a callable `bool(std::size_t iteration, double energy)`, called after each iteration
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(iteration_callback)
/// the steps of projected Taubin smoothing that give the starting point, a `std::size_t`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(initial_smoothing_steps)
/// a readable property map from vertices to numbers: each vertex's own tolerance
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(vertex_tolerance_map)
/// the half-extents of every vertex's box along x, y and z, a `std::array<double, 3>`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(box_half_extents)
/// a readable property map from vertices to their box's half-extents (three numbers)
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(vertex_box_half_extents_map)
/// a readable property map from vertices to their box's centre (a point)
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(vertex_box_center_map)
/// a writable property map from vertices to numbers: each vertex's distance to its input position
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(vertex_deviation_map)
/// a writable property map from vertices to `bool`: whether the vertex ended on its bound
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(vertex_at_bound_map)

/// what is minimized inside the bound, a `Constrained_fairing_objective`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(fairing_objective)
/// the weight of the fidelity term of the accurate objective, a `double`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(fidelity_weight)
/// the weight of the barrier against slivers, a `double`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(sliver_barrier_weight)
/// whether the vertices may also slide along the surface, a `bool`
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(tangential_motion)
/// the dihedral angle in degrees, a `double` in (0, 180), over which edges are detected as
/// creases, kept sharp
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(feature_angle)
/// a point set's neighbours per point, for its normals and tangent fans, a `std::size_t` of at
/// least 3 (`constrained_fairing_of_points()`)
CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER(number_of_neighbors)
#undef CGAL_PMP_CONSTRAINED_FAIRING_PARAMETER

} // namespace constrained_fairing_parameters

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_PARAMETERS_H
