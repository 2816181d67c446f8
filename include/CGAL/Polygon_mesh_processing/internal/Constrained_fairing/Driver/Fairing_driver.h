// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One call, for any kind of input, in the phases of the method:
//  - check: the input's structure, then every value (Value_check.h) in the order of the user's
//    vertices, so that the first defect is reported and nothing else is done;
//  - order: the vertices of the part that moves, in the Hilbert order of their input positions
//    (Hilbert_order.h), the one numbering of everything that follows; the bounds are read
//    straight into it;
//  - build: the hinges, the objective (bending energy, barrier against slivers, the input's own
//    terms, fidelity);
//  - descend (Fairing_descent.h): from a smoothed start, then re-seeded descents around the
//    folds it left (Fold_repair.h), with one solver; then the input's own repair;
//  - report and write back: the result, the output maps, and the points that moved.
// Each kind of input (Mesh_input.h, Interface_input.h) supplies only what differs:
//  - structure_error(), then part(maps): the vertices that take part and which of them stay
//    (size(), number(k), is_fixed(k), for_each_vertex(f) with f(k, key));
//  - input_points(part), and triangles(part), on the part's numbering, for the area check;
//  - order(part, rank): its own numbering moved to the solver's order;
//  - hinges(part, moving, X0, settings) and number_of_feature_edges() (the creases it keeps),
//    sliding_points(part) (those with no surface normal),
//    sliver_threshold(settings), add_terms(objective, mesh, X0, settings);
//  - repair(bound, moving, X0, X, objective, settings, result) after the descent;
//  - clear_outputs(maps) before the part's values are written, and write(key, x, y, z).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Bound_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Fidelity_anchor.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_descent.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Value_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hilbert_order.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>

#include <CGAL/assertions.h>
#include <CGAL/property_map.h>

#include <cstddef>
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

template <typename Input, typename VertexMaps, typename SparseLinearSolver>
Constrained_fairing_result run_fairing_driver(Input& input, double epsilon, const Fairing_settings& settings,
                                              const VertexMaps& maps, const Iteration_callback& callback,
                                              const SparseLinearSolver& solver)
{
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
    // build
    const Hinge_mesh mesh = input.hinges(part, moving, X0, settings);
    result.number_of_feature_edges = input.number_of_feature_edges();
    Fairing_objective energy(mesh, X0, settings.sliver_barrier_weight, input.sliver_threshold(settings));
    input.add_terms(energy, mesh, X0, settings);
    Points anchor;
    if(settings.is_accurate())
    {
      anchor = X0;
      Fidelity_anchor(mesh).apply(bound, anchor);
      energy.add_fidelity(settings.fidelity_weight, [&bound](std::size_t i) { return bound.size(i); }, anchor);
    }

    // descend
    Points X;
    const std::vector<bool> sliding = input.sliding_points(part);
    Fairing_descent<std::decay_t<decltype(bound)>, SparseLinearSolver>(mesh, bound, moving, sliding, settings, solver)
      .run(X0, energy, anchor, callback, X, result);
    if(!result)
      return;
    input.repair(mesh, bound, moving, X0, X, energy, settings, result);

    // report and write back; only moved points are written, the others keep their coordinates
    // exactly, even in an exact kernel
    count_bound(bound, moving, X, result);
    input.clear_outputs(maps);
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
  };
  if(bounds.is_box())
    fair(bounds.box(X0));
  else
    fair(std::move(bounds).ball(X0));
  return result;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
