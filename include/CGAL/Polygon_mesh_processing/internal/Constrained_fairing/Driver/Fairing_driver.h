// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One call, for any kind of input (the Input concept, Fairing_input.h), in the phases of the
// method:
//  - check: the input's structure, then every value (Value_check.h) in the order of the user's
//    vertices, so that the first defect is reported and nothing else is done;
//  - order: the vertices of the part that moves, in the Hilbert order of their input positions
//    (Hilbert_order.h), the one numbering of everything that follows; the bounds are read
//    straight into it;
//  - build: the hinges, the objective (bending energy, barrier against slivers, the input's own
//    terms, fidelity), the problem (Fairing_problem.h);
//  - fair: the step the caller gives, on the problem: the public functions fair it whole
//    (Fairing_descent.h: from a smoothed start, then re-seeded descents around the folds it
//    left, Fold_repair.h); a caller may fair it part by part instead; then the input's own
//    repair;
//  - report and write back: the result, the output maps, and the points that moved.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Bound_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_input.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_problem.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Value_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hilbert_order.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fidelity_term.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>

#include <CGAL/assertions.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Whether vertex i of X lies on its bound (a vertex that does not move does not count).
template <typename Bound>
bool is_at_bound(const Bound& bound, const std::vector<bool>& moving, const Points& X, std::size_t i)
{
  typename Bound::Face face;
  return moving[i] && bound.size(i) > 0 && bound.is_on_boundary(X, i, face);
}

// The result's largest deviation and its counts of the vertices at their bound and fixed.
template <typename Bound>
void count_bound(const Bound& bound, const std::vector<bool>& moving, const Points& X,
                 Constrained_fairing_result& result)
{
  result.max_deviation = bound.max_deviation(X);
  for(std::size_t i = 0; i < moving.size(); ++i)
  {
    result.number_of_vertices_at_bound += is_at_bound(bound, moving, X, i);
    result.number_of_fixed_vertices += !moving[i] || !(bound.size(i) > 0);
  }
}

// Report and write back: the result's counts, the output maps, and the points that moved;
// only those are written, the others keep their coordinates exactly, even in an exact kernel.
template <typename Input, typename Part, typename Bound, typename VertexMaps>
void write_back(Input& input, const Part& part, const std::vector<Index>& rank, const Bound& bound,
                const std::vector<bool>& moving, const Points& X0, const Points& X, const VertexMaps& maps,
                Constrained_fairing_result& result)
{
  count_bound(bound, moving, X, result);
  input.clear_outputs(maps);
  input.write_own_outputs();
  if constexpr(VertexMaps::has_deviation)
    part.for_each_vertex([&](std::size_t k, const auto& v) { put(maps.deviation, v, bound.deviation(X, rank[k])); });
  if constexpr(VertexMaps::has_at_bound)
    part.for_each_vertex(
      [&](std::size_t k, const auto& v) { put(maps.at_bound, v, is_at_bound(bound, moving, X, rank[k])); });
  part.for_each_vertex([&](std::size_t k, const auto& v) {
    const std::size_t i = rank[k];
    if(point(X, i) != point(X0, i))
      input.write(v, X(i, 0), X(i, 1), X(i, 2));
  });
}

// Build, fair by `fair_step(problem, X, result)`, repair, report and write back, within `bound`.
template <typename Input, typename Part, typename Bound, typename VertexMaps, typename SparseLinearSolver,
          typename FairStep>
void fair_within(Input& input, const Part& part, const std::vector<Index>& rank, const Points& X0,
                 const std::vector<bool>& moving, const Bound& bound, const Fairing_settings& settings,
                 const VertexMaps& maps, const SparseLinearSolver& solver, const FairStep& fair_step,
                 Constrained_fairing_result& result)
{
  // build
  const Hinge_mesh mesh = input.hinges(part, moving, X0, settings);
  result.number_of_feature_edges = input.number_of_feature_edges();
  const double sliver_threshold = input.sliver_threshold(settings);
  // An input without hinges brings its bending energy as a term (Operator_bending.h).
  Fairing_objective energy = Input::bends_by_hinges
                               ? Fairing_objective(mesh, X0, settings.sliver_barrier_weight, sliver_threshold)
                               : Fairing_objective();
  input.add_terms(energy, mesh, X0, settings);
  Points anchor;
  std::optional<Fidelity_term> fidelity;
  if(settings.is_accurate())
  {
    anchor = X0;
    input.denoise(mesh, bound, anchor);
    fidelity.emplace(settings.fidelity_weight, [&bound](std::size_t i) { return bound.size(i); }, anchor);
    energy.add_term(*fidelity);
  }
  const std::vector<bool> sliding = input.sliding_points(part);
  Fairing_problem<Bound, SparseLinearSolver> problem(
    Built_problem<Bound>{mesh, bound, moving, sliding, X0, rank, energy, anchor, sliver_threshold}, settings, solver);

  // fair
  Points X;
  fair_step(problem, X, result);
  if(!result)
    return;
  input.repair(mesh, bound, moving, X0, X, energy, settings, result);
  write_back(input, part, rank, bound, moving, X0, X, maps, result);
}

// The phases of a call, its fair step `fair_step(problem, X, result)` the caller's.
template <typename Input, typename VertexMaps, typename SparseLinearSolver, typename FairStep>
Constrained_fairing_result run_fairing_phases(Input& input, double epsilon, const Fairing_settings& settings,
                                              const VertexMaps& maps, const SparseLinearSolver& solver,
                                              const FairStep& fair_step)
{
  static_assert(check_fairing_input<Input, VertexMaps>());
  CGAL_precondition(settings.options.threshold >= 0);
  Constrained_fairing_result result;
  const auto reject = [&result](Input_error error) {
    result.defect = error.defect;
    result.message = std::move(error.message);
    return std::move(result);
  };

  // check
  if(Input_error error = input.structure_error())
    return reject(std::move(error));
  const auto part = input.part(maps);
  if(part.size() == 0) // an empty face range: nothing to do
  {
    result.status = Constrained_fairing_status::CONVERGED;
    return result;
  }
  Points X0 = input.input_points(part);
  const auto triangles = [&]() -> decltype(auto) { return input.triangles(part); };
  if(Input_error error = value_error(part, X0, triangles, epsilon, settings, maps))
    return reject(std::move(error));

  // order
  const std::vector<Index> rank = hilbert_rank(X0);
  Bound_parameters bounds(part, rank, epsilon, settings.is_box(), settings.uniform_box_half_extents(), maps);
  {
    Points ordered(X0.rows(), 3);
    for(std::size_t k = 0; k < part.size(); ++k)
      point(ordered, rank[k]) = point(X0, k);
    X0.swap(ordered);
  }
  std::vector<bool> moving(part.size());
  for(std::size_t k = 0; k < part.size(); ++k)
    moving[rank[k]] = !part.is_fixed(k);
  input.order(part, rank);

  const auto fair = [&](const auto& bound) {
    fair_within(input, part, rank, X0, moving, bound, settings, maps, solver, fair_step, result);
  };
  if(bounds.is_box())
    fair(bounds.box(X0));
  else
    fair(std::move(bounds).ball(X0));
  return result;
}

// A call of the public functions: the problem faired whole.
template <typename Input, typename VertexMaps, typename SparseLinearSolver>
Constrained_fairing_result run_fairing_driver(Input& input, double epsilon, const Fairing_settings& settings,
                                              const VertexMaps& maps, const Iteration_callback& callback,
                                              const SparseLinearSolver& solver)
{
  return run_fairing_phases(input, epsilon, settings, maps, solver,
                            [&callback](const auto& problem, Points& X, Constrained_fairing_result& result) {
                              problem.fair(callback, X, result);
                            });
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
