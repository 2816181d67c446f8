// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The method once a driver has built the problem (the hinges, the bound, the objective): a
// smoothed start, kept only if it lowers the objective, so that the result never has a higher
// objective than the input; the descent by the method the settings name; then re-seeded
// descents around the folds it left (Fold_repair.h), with the same solver. It fills the
// result's energies, counts, status and message; the driver (Fairing_driver.h) reports the rest
// and writes back.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DESCENT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DESCENT_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Normal_offsets.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Smoothed_start.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Active_set_newton.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Fold_repair.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Projected_lbfgs.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_report.h>

#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Bound, typename SparseLinearSolver>
class Fairing_descent
{
public:
  // `moving[i]`: whether vertex i may move (fold repair re-seeds only those); `sliding[i]`:
  // whether it has no surface normal, and moves freely in its set even where the others move
  // along the normals (empty: none).
  Fairing_descent(const Hinge_mesh& mesh, const Bound& bound, const std::vector<bool>& moving,
                  const std::vector<bool>& sliding, const Fairing_settings& settings, const SparseLinearSolver& solver)
    : m_mesh(mesh), m_bound(bound), m_moving(moving), m_sliding(sliding), m_settings(settings), m_solver(solver)
  {}

  // From the input points X0 to X, minimizing `energy`, whose fidelity term (the accurate
  // objective) pulls towards `anchor`.
  void run(const Points& X0, Fairing_objective& energy, const Points& anchor, const Iteration_callback& callback,
           Points& X, Constrained_fairing_result& result) const
  {
    begin(X0, energy, result);
    X = X0;
    if(m_settings.options.max_iterations == 0)
      return;
    start(X0, energy, anchor, result.initial_energy, X);
    descend(energy, callback, slides() ? Points() : normal_directions(X), X, result);
  }

  // The result's energies and counts at X0, before any iteration.
  void begin(const Points& X0, Fairing_objective& energy, Constrained_fairing_result& result) const
  {
    result.initial_energy = result.final_energy = energy.value(X0);
    result.initial_bending_energy = result.final_bending_energy = energy.bending_energy(X0);
    result.number_of_degenerate_edges = energy.number_of_degenerate_hinges();
    result.status = Constrained_fairing_status::ITERATION_LIMIT_REACHED;
  }

  // The start from X0: the accurate objective's anchor, or X0 smoothed, kept if it lowers the
  // energy below `initial_energy`.
  void start(const Points& X0, Fairing_objective& energy, const Points& anchor, double initial_energy,
             Points& X) const
  {
    if(m_settings.options.smoothing_steps == 0)
      return;
    if(m_settings.is_accurate())
      X = anchor;
    else
      smooth_start(m_mesh, m_bound, m_settings.options.smoothing_steps, X);
    if(!(energy.value(X) < initial_energy))
      X = X0;
  }

  // Whether the vertices slide in their sets, rather than move along the normals of the start.
  bool slides() const { return m_settings.slides(std::is_same<Bound, Box_bound>::value); }

  // From X by the method the settings name, over the bound's sets if the vertices slide, or else
  // over the segments inside them of the lines through X along `normals` (Normal_offsets.h).
  void descend(Fairing_objective& energy, const Iteration_callback& callback, const Points& normals, Points& X,
               Constrained_fairing_result& result) const
  {
    if(slides())
      solve_over(m_bound, energy, callback, X, result);
    else
    {
      const Normal_offset_bound<Bound> segments(m_bound, X, normals);
      Normal_offset_objective<Fairing_objective, Bound> offsets(energy, segments);
      solve_over(segments, offsets, callback, X, result);
    }
    if(result)
      result.final_bending_energy = energy.bending_energy(X);
  }

  // Each vertex's unit normal at X; none (it moves freely) where the input has no surface
  // normal (a mesh's creases, a label map's junction lines), where the normal vanishes, and at
  // the triangles folded at X, which no motion along the normals would unfold.
  Points normal_directions(const Points& X) const
  {
    Points N = vertex_normals(m_mesh, X);
    for(Index f : folded_triangles(m_mesh, X))
      for(Index v : m_mesh.triangles[f])
        point(N, v).setZero();
    for(std::size_t i = 0; i < m_sliding.size(); ++i)
      if(m_sliding[i])
        point(N, i).setZero();
    return N;
  }

private:
  template <typename Feasible_set, typename Objective>
  void solve_over(const Feasible_set& bound, Objective& energy, const Iteration_callback& callback, Points& X,
                  Constrained_fairing_result& result) const
  {
    std::optional<Projected_lbfgs<Feasible_set, Objective> > quasi_newton;
    std::optional<Active_set_newton<Feasible_set, SparseLinearSolver, Objective> > active_set;
    if(m_settings.method == Constrained_fairing_method::QUASI_NEWTON)
      quasi_newton.emplace(bound, energy);
    else
      active_set.emplace(m_mesh, bound, energy, m_solver);
    const auto descend = [&](const Solver_options& options, const Iteration_callback& heard, Points& Y) {
      return quasi_newton ? quasi_newton->run(Y, options, heard) : active_set->run(Y, options, heard);
    };
    Solver_report path = descend(m_settings.options, callback, X);
    if(path.status != Constrained_fairing_status::LINEAR_SOLVER_FAILED)
    {
      const Fold_count folds = repair_folds(m_mesh, bound, m_moving, descend, m_settings.options, callback, X, path);
      result.number_of_folded_faces = folds.after;
      result.number_of_unfolded_faces = folds.before > folds.after ? folds.before - folds.after : 0;
      result.final_energy = path.final_energy;
    }
    result.status = path.status;
    result.message = path.message;
    result.number_of_iterations = path.iterations;
    result.number_of_cg_iterations = path.cg_iterations;
    result.number_of_energy_evaluations = path.energy_evaluations;
  }

  const Hinge_mesh& m_mesh;
  const Bound& m_bound;
  const std::vector<bool>& m_moving;
  const std::vector<bool>& m_sliding;
  const Fairing_settings& m_settings;
  const SparseLinearSolver& m_solver;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DESCENT_H
