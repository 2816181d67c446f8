// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A call's problem once the driver (Fairing_driver.h) has checked, ordered and built it: the
// hinges, the bound, the objective, which vertices move and which slide. It is faired whole,
// as the public functions do (Fairing_descent.h), or part by part with the rest frozen, as
// often as needed (Part_problem.h): from the start of the whole (its smoothed start, and the
// normals there along which the vertices move), each part descends over its own hinges, at a
// cost proportional to the part. A part's objective is the bending energy of its hinges with
// the barrier against slivers, and the fidelity term of the accurate objective; the input's
// own terms (a mesh's creases, a multi-label surface's volumes) are the whole's only.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_PROBLEM_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_PROBLEM_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_descent.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Part_problem.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fidelity_term.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// What a problem is built of; the driver owns it all, the problem keeps references.
template <typename Bound>
struct Built_problem
{
  const Hinge_mesh& mesh;
  const Bound& bound;
  const std::vector<bool>& moving;
  const std::vector<bool>& sliding;
  const Points& X0;         // the input points, in the solver's order
  const std::vector<Index>& rank; // the solver's place of the input's k-th vertex
  Fairing_objective& energy;
  const Points& anchor;     // the accurate objective's, else empty
  double sliver_threshold;  // the input's
};

template <typename Bound, typename SparseLinearSolver>
class Fairing_problem
{
public:
  Fairing_problem(const Built_problem<Bound>& built, const Fairing_settings& settings, const SparseLinearSolver& solver)
    : m_built(built), m_settings(settings), m_solver(solver),
      m_descent(built.mesh, built.bound, built.moving, built.sliding, settings, solver)
  {}

  const Built_problem<Bound>& built() const { return m_built; }

  // The whole at once, from the input points to X.
  void fair(const Iteration_callback& callback, Points& X, Constrained_fairing_result& result) const
  {
    m_descent.run(m_built.X0, m_built.energy, m_built.anchor, callback, X, result);
  }

  // The whole's start, from which the parts descend, into X; the result's initial energies.
  void start(Points& X, Constrained_fairing_result& result)
  {
    m_descent.begin(m_built.X0, m_built.energy, result);
    X = m_built.X0;
    m_descent.start(m_built.X0, m_built.energy, m_built.anchor, result.initial_energy, X);
    if(!m_descent.slides())
      m_normals = m_descent.normal_directions(X);
    m_tables.emplace(m_built.mesh);
    m_number_of_moving = 0;
    for(std::size_t i = 0; i < m_built.moving.size(); ++i)
      m_number_of_moving += m_built.bound.size(i) > 0;
  }

  // The vertices `part` (sorted, each once) faired from X with the others frozen at X, after
  // start(), in at most `max_iterations` (and the settings' number); X gets the part's new
  // points. Returns the part's descent. A sweep over parts need not end each part's descent:
  // the next sweep goes on from where it stopped.
  Constrained_fairing_result fair_part(const std::vector<Index>& part, const Iteration_callback& callback, Points& X,
                                       std::size_t max_iterations = std::numeric_limits<std::size_t>::max())
  {
    CGAL_precondition(m_tables.has_value());
    const Part_problem piece(m_built.mesh, m_built.moving, part, *m_tables);
    const std::vector<bool> moves = piece.moves();
    const Points input = piece.rows_of(m_built.X0);
    Points centres = piece.rows_of(X);
    for(std::size_t k = 0; k < piece.number_of_moving_vertices(); ++k)
      point(centres, k) = point(input, k);
    const Bound bound = m_built.bound.part(centres, piece.vertices(), moves);
    Fairing_objective energy(piece.mesh(), input, m_settings.sliver_barrier_weight, m_built.sliver_threshold);
    std::optional<Fidelity_term> fidelity;
    Points anchor;
    if(m_built.anchor.rows() > 0)
    {
      anchor = piece.rows_of(m_built.anchor);
      add_fidelity(piece, bound, anchor, energy, fidelity);
    }
    std::vector<bool> sliding(m_built.sliding.empty() ? 0 : piece.vertices().size());
    for(std::size_t k = 0; k < sliding.size(); ++k)
      sliding[k] = m_built.sliding[piece.vertices()[k]];
    Points Y = piece.rows_of(X);
    Constrained_fairing_result result;
    Fairing_settings settings = m_settings;
    settings.options.max_iterations = (std::min)(settings.options.max_iterations, max_iterations);
    Fairing_descent<Bound, SparseLinearSolver> descent(piece.mesh(), bound, moves, sliding, settings, m_solver);
    descent.begin(Y, energy, result);
    descent.descend(energy, callback, m_normals.rows() > 0 ? piece.rows_of(m_normals) : Points(), Y, result);
    piece.write_moving(Y, X);
    return result;
  }

  // The whole's energies at X, after the parts.
  void finish(const Points& X, Constrained_fairing_result& result) const
  {
    result.final_energy = m_built.energy.value(X);
    result.final_bending_energy = m_built.energy.bending_energy(X);
  }

private:
  // The whole's fidelity weights: mu over the whole's count of vertices that move, not the part's.
  void add_fidelity(const Part_problem& piece, const Bound& bound, const Points& anchor, Fairing_objective& energy,
                    std::optional<Fidelity_term>& fidelity) const
  {
    std::size_t moving = 0;
    for(std::size_t k = 0; k < piece.vertices().size(); ++k)
      moving += bound.size(k) > 0;
    const double mu = m_settings.fidelity_weight * double(moving) / double(m_number_of_moving);
    fidelity.emplace(mu, [&bound](std::size_t k) { return bound.size(k); }, anchor);
    energy.add_term(*fidelity);
  }

  Built_problem<Bound> m_built;
  const Fairing_settings& m_settings;
  const SparseLinearSolver& m_solver;
  Fairing_descent<Bound, SparseLinearSolver> m_descent;
  Points m_normals; // the whole's start's, empty where the vertices slide
  std::size_t m_number_of_moving = 0; // the whole's vertices of a nonzero bound
  std::optional<Part_tables> m_tables;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_PROBLEM_H
