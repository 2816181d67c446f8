// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The active set Newton method with gradient projection of the paper (Section 4). Each
// iteration:
//  1. Cauchy step: along P(x - t g), accept y with E(y) < E(x) + lambda <g, y - x>;
//  2. subspace minimization: along P(y + t v), v the reduced Newton direction at y on the
//     face of the feasible set that contains y, accept a point with lower energy than y.
// The projected gradient method does step 1 only. Every accepted point lies in the feasible
// set and has a lower energy than the one before, so the energy never rises.
//
// The energy is an Objective (see Projected_line_search.h), Fairing_objective by default; the
// subspace step models its Hessian by the thin plate one of the mesh, whatever the objective.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_NEWTON_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_NEWTON_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Active_set.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Projected_line_search.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Reduced_newton_direction.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_report.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Stopping_rule.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Thin_plate_hessian.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Bound, typename SparseLinearSolver, typename Objective = Fairing_objective>
class Active_set_newton
{
public:
  // lambda of the sufficient decrease condition (3)
  static constexpr double sufficient_decrease = 0.01;

  // `energy` is the objective on `mesh`, set up on the input points. The thin plate model of
  // its Hessian leaves out the fidelity term of the accurate objective: a rougher model, which
  // the line search makes up for.
  Active_set_newton(const Hinge_mesh& mesh, const Bound& bound, Objective& energy,
                    const SparseLinearSolver& solver)
    : m_mesh(mesh), m_bound(bound), m_energy(energy), m_solver(solver)
  {}

  // Fairs X, feasible on entry, in place. `callback(iteration, energy)` returning false
  // cancels. On LINEAR_SOLVER_FAILED, X holds the last iterate (the input if the
  // factorization failed) and final_energy its energy (0 if the factorization failed). The model
  // Hessian depends only on the input points: it is factorized by the first run, and the
  // later ones (fold repair) reuse it.
  template <typename Callback>
  Solver_report run(Points& X, const Solver_options& options, const Callback& callback)
  {
    Solver_report report;
    const bool newton = !options.cauchy_steps_only;
    if(newton && !m_hessian)
    {
      m_hessian = std::make_unique<Thin_plate_hessian<SparseLinearSolver> >(m_mesh, m_bound.input_points(), m_solver);
      if(!m_hessian->factorize())
      {
        m_hessian.reset();
        report.status = Constrained_fairing_status::LINEAR_SOLVER_FAILED;
        report.message = "the sparse linear solver could not factorize the stiffness matrix";
        return report;
      }
    }

    const std::size_t evaluations_before = m_search.evaluations();
    double E = m_energy.value_and_gradient(X, m_G, nullptr);
    Stopping_rule history(options);
    history.push(E);
    // The first Cauchy step moves the vertex of largest gradient by epsilon.
    const double largest_gradient = m_G.rowwise().norm().maxCoeff();
    double t_cauchy = largest_gradient > 0 ? m_bound.largest_size() / largest_gradient : 0;
    double t_newton = 1;

    while(report.iterations < options.max_iterations)
    {
      if(!(E > 0) || !(t_cauchy > 0))
      {
        report.status = Constrained_fairing_status::CONVERGED;
        break;
      }

      const auto sufficient = [&](double e, const Points& Y) {
        return e < E + sufficient_decrease * (m_G.cwiseProduct(Y - X)).sum();
      };
      m_D.noalias() = -m_G;
      Projected_line_search::Accepted cauchy{m_Y};
      if(!m_search.search(X, E, m_D, t_cauchy, m_bound, m_energy, sufficient, cauchy))
      {
        // No point of the projected gradient path decreases the energy: X is stationary
        // up to rounding.
        report.status = Constrained_fairing_status::CONVERGED;
        break;
      }
      t_cauchy = cauchy.step;

      if(newton)
      {
        m_energy.value_and_gradient(m_Y, m_G, nullptr);
        m_active.compute(m_bound, m_Y);
        if(!m_direction.compute(m_G, m_active, *m_hessian, (std::max)(std::size_t(1), options.cg_iterations), m_D, report.cg_iterations))
        {
          report.status = Constrained_fairing_status::LINEAR_SOLVER_FAILED;
          report.message = "the sparse linear solver failed in a Newton step";
          break;
        }
        const auto decreases = [](double, const Points&) { return true; }; // below the Cauchy point's
        Projected_line_search::Accepted subspace{m_Z};
        if(m_search.search(m_Y, cauchy.energy, m_D, t_newton, m_bound, m_energy, decreases, subspace))
        {
          t_newton = subspace.step;
          m_Y.swap(m_Z);
        }
      }
      // m_Y is the accepted point: it becomes the iterate.
      X.swap(m_Y);
      E = m_energy.value_and_gradient(X, m_G, nullptr);
      if(!history.next_iteration(E, callback, report))
        break;
    }
    report.final_energy = E;
    report.energy_evaluations = m_search.evaluations() - evaluations_before + 1 + (newton ? 2 : 1) * report.iterations;
    return report;
  }

private:
  const Hinge_mesh& m_mesh;
  const Bound& m_bound;
  Objective& m_energy;
  SparseLinearSolver m_solver;
  std::unique_ptr<Thin_plate_hessian<SparseLinearSolver> > m_hessian;
  Active_set<Bound> m_active;
  Reduced_newton_direction m_direction;
  Projected_line_search m_search;
  Points m_G, m_D, m_Y, m_Z; // gradient, search direction, Cauchy point, subspace point
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_NEWTON_H
