// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The active set Newton method with gradient projection (Section 4). Each iteration:
//  1. Cauchy step: along P(x - t g), accept y with E(y) < E(x) + lambda <g, y - x>;
//  2. subspace minimization: along P(y + t v), v the reduced Newton direction at y, accept
//     a point with lower energy than y.
// The projected gradient method does step 1 only. Every accepted point lies in the feasible
// set and has a lower energy than the one before, so the energy never rises.
//
// Stopping rule: the projected gradient's norm is not monotone and a poor criterion; the
// relative energy decrease is. The method stops when the energy decreased by less than
// `threshold` per iteration, on average over the last `window` iterations.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_NEWTON_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_NEWTON_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Feasible_set.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Projected_line_search.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Reduced_newton_direction.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Thin_plate_hessian.h>

#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Solver_options
{
  Constrained_fairing_method method = Constrained_fairing_method::ACTIVE_SET_NEWTON;
  std::size_t max_iterations = 200;
  double threshold = 1e-3;
  // S M^-1 S models the energy only roughly once many vertices sit on their bounds, so
  // solving the model better does not pay. On the 37 k vertex bunny, 3 and 10 iterations per
  // step needed more than 2 and 3 times longer to reach the energy that 1 reaches at epsilon = 0.25
  // mean edge lengths, and did not reach it in 200 iterations at 2 mean edge lengths
  // (benchmark/fairing_quality compares them).
  std::size_t cg_iterations = 1;
};

template <typename SparseLinearSolver>
class Active_set_newton
{
public:
  // lambda of the sufficient decrease condition (3)
  static constexpr double sufficient_decrease = 0.01;
  static constexpr std::size_t window = 3;

  // `energy` is the bending energy of `mesh`, set up on X0.
  Active_set_newton(const Hinge_mesh& mesh, const Points& X0, const Feasible_set& omega, Bending_energy energy,
                    const SparseLinearSolver& solver)
    : m_mesh(mesh), m_X0(X0), m_omega(omega), m_energy(std::move(energy)), m_solver(solver)
  {}

  // Fairs X, feasible on entry, in place. `callback(iteration, energy)` returning false
  // cancels. On LINEAR_SOLVER_FAILED, X holds an intermediate iterate: discard it.
  template <typename Callback>
  void run(Points& X, const Solver_options& options, const Callback& callback,
           Constrained_fairing_result& result)
  {
    const bool newton = options.method == Constrained_fairing_method::ACTIVE_SET_NEWTON;
    if(newton && !factorize_hessian())
    {
      result.status = Constrained_fairing_status::LINEAR_SOLVER_FAILED;
      result.message = "the sparse linear solver could not factorize the stiffness matrix";
      return;
    }

    double E = m_energy.value_and_gradient(X, m_G);
    std::vector<double> history{E};
    result.status = Constrained_fairing_status::ITERATION_LIMIT_REACHED;
    // The first Cauchy step moves the vertex of largest gradient by epsilon.
    const double largest_gradient = m_G.rowwise().norm().maxCoeff();
    double t_cauchy = largest_gradient > 0 ? m_omega.epsilon() / largest_gradient : 0;
    double t_newton = 1;

    while(result.number_of_iterations < options.max_iterations)
    {
      if(!(E > 0) || !(t_cauchy > 0))
      {
        result.status = Constrained_fairing_status::CONVERGED;
        break;
      }

      const auto sufficient = [&](double e, const Points& Y) {
        return e < E + sufficient_decrease * m_G.cwiseProduct(Y - X).sum();
      };
      m_D.noalias() = -m_G;
      if(!m_cauchy.run(X, m_D, t_cauchy, m_omega, m_energy, sufficient))
      {
        // No point of the projected gradient path decreases the energy: X is stationary
        // up to rounding.
        result.status = Constrained_fairing_status::CONVERGED;
        break;
      }
      t_cauchy = m_cauchy.step();
      Points& Y = m_cauchy.point();
      const double E_y = m_cauchy.energy();

      if(newton)
      {
        m_energy.value_and_gradient(Y, m_G);
        if(!m_direction.compute(Y, m_G, m_omega, *m_hessian, options.cg_iterations, m_D,
                                 result.number_of_cg_iterations))
        {
          result.status = Constrained_fairing_status::LINEAR_SOLVER_FAILED;
          result.message = "the sparse linear solver failed in a Newton step";
          return;
        }
        const auto decreases = [&](double e, const Points&) { return e < E_y; };
        if(m_subspace.run(Y, m_D, t_newton, m_omega, m_energy, decreases))
        {
          t_newton = m_subspace.step();
          Y.swap(m_subspace.point());
        }
      }
      // Y is the accepted point: it becomes the iterate.
      X.swap(Y);
      E = m_energy.value_and_gradient(X, m_G);
      history.push_back(E);
      ++result.number_of_iterations;

      if(!callback(result.number_of_iterations, E))
      {
        result.status = Constrained_fairing_status::CANCELLED;
        break;
      }
      if(history.size() > window)
      {
        const double before = history[history.size() - 1 - window];
        if(before - E <= window * options.threshold * before)
        {
          result.status = Constrained_fairing_status::CONVERGED;
          break;
        }
      }
    }
    result.initial_energy = history.front();
    result.final_energy = E;
  }

private:
  bool factorize_hessian()
  {
    m_hessian = std::make_unique<Thin_plate_hessian<SparseLinearSolver> >(m_mesh, m_X0, m_solver);
    return m_hessian->factorize();
  }

  const Hinge_mesh& m_mesh;
  const Points& m_X0;
  const Feasible_set& m_omega;
  Bending_energy m_energy;
  SparseLinearSolver m_solver;
  std::unique_ptr<Thin_plate_hessian<SparseLinearSolver> > m_hessian;
  Reduced_newton_direction m_direction;
  Projected_line_search m_cauchy, m_subspace;
  Points m_G, m_D; // gradient, search direction
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_NEWTON_H
