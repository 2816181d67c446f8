// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Folds (Folded_triangles.h) left by the descent. At heavy noise the descent keeps some of the
// input's: no step may flip or collapse a triangle (Projected_lbfgs.h limits each move to a tenth
// of the vertex's reach), so a triangle folded at the start stays folded, held there by the bound
// and by its neighbours, a local minimum of the energy. The repair re-seeds the vertices of the
// folded triangles and of their neighbours: a few projected Laplacian steps on them alone, each
// vertex moved to the mean of its neighbours and back into its bound, which opens the fold since
// the bound allows the flat configuration around it; it then descends again from there and keeps
// the outcome only if its objective ends lower.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_REPAIR_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_REPAIR_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Folded_triangles.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_report.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The Laplacian steps of a re-seed.
constexpr std::size_t reseed_steps = 10;

// The rounds of fold repair at most.
constexpr std::size_t fold_repair_rounds = 3;

// A round is followed by another only if it undid at least this share of the folds it
// re-seeded. Each round costs about as much as the stopping rule's two windows, whatever the
// number of folds; after a round that undid less than half, the next undid almost none (0, 0,
// 0, 0, 1, 2, 2 and 50 folds, or left 6 and 12 more: three calls on two noisy meshes of CGAL's
// demo data, seven atlases of mricron-data; doc/design_notes.md, "Fold repair and what the
// callback hears").
constexpr double fold_repair_share = 0.5;

// Re-seeds the vertices of the `folded` triangles and their neighbours in X, which stays
// feasible.
template <typename Bound>
void reseed_folds(const Hinge_mesh& mesh, const Bound& bound, const std::vector<Index>& folded, Points& X)
{
  const std::size_t n = static_cast<std::size_t>(X.rows());
  std::vector<bool> in_fold(n, false), moves(n, false);
  for(Index f : folded)
    for(Index v : mesh.triangles[f])
      in_fold[v] = true;
  for(const auto& t : mesh.triangles)
    if(in_fold[t[0]] || in_fold[t[1]] || in_fold[t[2]])
      for(Index v : t)
        moves[v] = true;
  Neighbour_mean neighbours(mesh, [&](std::size_t i) { return bool(moves[i]); });
  for(std::size_t step = 0; step < reseed_steps; ++step)
  {
    neighbours.gather(X);
    for(std::size_t i = 0; i < n; ++i)
      if(neighbours.count(i) > 0)
      {
        point(X, i) = neighbours.mean(i);
        bound.project(X, i);
      }
  }
}

// The folds of X among the triangles with a vertex that moves, before and after the repair.
struct Fold_count
{
  std::size_t before = 0, after = 0;
};

// Repairs the folds of X, where a descent ended with `path` (its iterations are those the
// callback heard, numbered from 1). Each round re-seeds the folds of the triangles with a
// `moving` vertex and descends again by `descend(options, callback, Y)`, within the
// iterations left of options.max_iterations. Until the round's objective gets below the one
// reached before it, the callback hears nothing; from there on each iterate is lower than
// all the path's, so the round is kept and the callback hears it with the path's next
// numbers. A round that never gets below is dropped, its work counted in the evaluations
// only; the rounds stop at the first that does not undo `fold_repair_share` of its folds.
template <typename Bound, typename Descend, typename Callback>
Fold_count repair_folds(const Hinge_mesh& mesh, const Bound& bound, const std::vector<bool>& moving,
                        const Descend& descend, const Solver_options& options, const Callback& callback, Points& X,
                        Solver_report& path)
{
  const auto folds = [&](const Points& Y) { return folded_moving_triangles(mesh, moving, Y); };
  std::vector<Index> folded = folds(X);
  Fold_count count;
  count.before = folded.size();
  for(std::size_t round = 0; round < fold_repair_rounds && !folded.empty() &&
                             path.status != Constrained_fairing_status::CANCELLED &&
                             path.iterations < options.max_iterations;
      ++round)
  {
    Solver_options left = options;
    left.max_iterations = options.max_iterations - path.iterations;
    Points Y = X;
    reseed_folds(mesh, bound, folded, Y);
    double lowest = path.final_energy;
    std::size_t heard = path.iterations;
    const auto below = [&](std::size_t, double e) {
      if(!(e < lowest))
        return true;
      lowest = e;
      return bool(callback(++heard, e));
    };
    const Solver_report again = descend(left, Iteration_callback(below), Y);
    path.cg_iterations += again.cg_iterations;
    path.energy_evaluations += again.energy_evaluations;
    if(heard == path.iterations)
      break;
    // A linear solver that fails midway (Newton method) leaves the last iterate, which was
    // heard: the round ends there, with the status of the path before it.
    const bool failed = again.status == Constrained_fairing_status::LINEAR_SOLVER_FAILED;
    path.iterations = heard;
    path.final_energy = lowest;
    if(!failed)
      path.status = again.status;
    X.swap(Y);
    std::vector<Index> left_folded = folds(X);
    const bool worth_another = double(left_folded.size()) <= (1 - fold_repair_share) * double(folded.size());
    folded.swap(left_folded);
    if(failed || !worth_another)
      break;
  }
  count.after = folded.size();
  return count;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FOLD_REPAIR_H
