// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a call of constrained_fairing() asks besides its per-vertex maps: the method, the
// objective and the solver's options. The defaults live here and only here, with why they were
// chosen; the named parameters are read once, by read_fairing_settings(), and a front end that
// has its options in another form (the Python module) sets only the fields its user gave.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_SETTINGS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_SETTINGS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_options.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

using Default_sparse_linear_solver =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;

// The accurate objective's fidelity weight, chosen on the benchmark fairing_accuracy over its
// whole set of meshes and noise levels (the user manual gives the alternatives' figures). Its
// anchor is made by Fidelity_anchor.h.
constexpr double default_fidelity_weight = 1e4;

// The weight of the barrier against slivers (Sliver_barrier.h), per triangle: at 1, a needle of
// 1.5 degrees costs 0.92, about as much as a right-angle bend between two equilateral triangles
// (0.87). On the benchmark fairing_accuracy, weights 0.5, 1 and 2 gave the same distance to the
// truth, normals and energies; the smallest angle over the set was 1.7, 1.8 and 2.2 degrees
// (accurate objective) and 2.3, 2.6 and 2.7 (fairest).
constexpr double default_sliver_barrier_weight = 1;

// The stopping rule of each method when the user sets none: the quasi-Newton method's energy
// keeps decreasing in small, uneven steps, with plateaus of tens of iterations, long after the
// noise is gone, so it is judged over 50 iterations and against a smaller threshold, and it
// stops only once the decrease still to come, extrapolated from the last two windows, is at
// most 1 % of the energy (Stopping_rule.h): on large meshes each iteration gains less, and the
// threshold alone stopped the call early there. On energy traces of the noisy bunny with no
// stopping rule (2000 iterations at 75 k, 300 k and 1.2 M triangles, 1000 at 4.8 M and 19.3 M),
// 1 % stops within 1.5, 1.8 and 0.8 % of the energy of 1000 iterations up to 1.2 M, and runs on
// at 4.8 M and 19.3 M, where the threshold alone stopped 2.9 and 7.7 % above it (after 704 and
// 264 iterations; the smallest extrapolated remainder while the threshold held was 1.9 and
// 1.5 %, so 2 % would have stopped at 19.3 M). It starts from a smoothed input
// (Smoothed_start.h); the paper's methods start from the input.
inline Solver_options default_options(Constrained_fairing_method method)
{
  Solver_options options;
  if(method == Constrained_fairing_method::QUASI_NEWTON)
  {
    options.threshold = 1.25e-4;
    options.window = 50;
    options.remaining_fraction = 0.01;
    options.max_iterations = 1000;
    options.smoothing_steps = 16;
  }
  options.cauchy_steps_only = method == Constrained_fairing_method::PROJECTED_GRADIENT;
  return options;
}

struct Fairing_settings
{
  explicit Fairing_settings(Constrained_fairing_method m = Constrained_fairing_method::QUASI_NEWTON)
    : method(m), options(default_options(m))
  {}

  // The accurate objective: a fidelity term of weight `fidelity_weight` (> 0) is added.
  bool is_accurate() const { return objective == Constrained_fairing_objective::ACCURATE && fidelity_weight > 0; }

  Constrained_fairing_method method;
  Solver_options options;
  Constrained_fairing_objective objective = Constrained_fairing_objective::FAIREST;
  double fidelity_weight = default_fidelity_weight;
  double sliver_barrier_weight = default_sliver_barrier_weight;
};

// The settings that `np` gives, each one it does not give at its default.
template <typename NamedParameters>
Fairing_settings read_fairing_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Fairing_settings settings(
    choose_parameter(get_parameter(np, fairing_method), Constrained_fairing_method::QUASI_NEWTON));
  Solver_options& options = settings.options;
  options.max_iterations = static_cast<std::size_t>(
    choose_parameter(get_parameter(np, internal_np::number_of_iterations), options.max_iterations));
  options.threshold = choose_parameter(get_parameter(np, energy_decrease_threshold), options.threshold);
  options.cg_iterations = static_cast<std::size_t>(
    choose_parameter(get_parameter(np, conjugate_gradient_iterations), options.cg_iterations));
  options.smoothing_steps =
    static_cast<std::size_t>(choose_parameter(get_parameter(np, initial_smoothing_steps), options.smoothing_steps));
  settings.objective = choose_parameter(get_parameter(np, fairing_objective), settings.objective);
  settings.fidelity_weight = choose_parameter(get_parameter(np, fidelity_weight), settings.fidelity_weight);
  settings.sliver_barrier_weight =
    choose_parameter(get_parameter(np, sliver_barrier_weight), settings.sliver_barrier_weight);
  return settings;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_SETTINGS_H
