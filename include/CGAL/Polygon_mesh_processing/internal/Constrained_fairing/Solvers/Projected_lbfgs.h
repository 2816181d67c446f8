// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default solver: a projected limited-memory BFGS method on the binding constraints.
//
// Why not the paper's Newton method: its model of the Hessian, S M^-1 S on the input mesh, is
// fixed and treats every direction of a vertex alike, while the bending energy of a noisy mesh
// is stiff along the surface normal and soft along the surface, and far stiffer on small or
// needle triangles than on the others. Quasi-Newton pairs learn the curvature from the
// gradients themselves, with no factorization, and cost one energy and gradient evaluation per
// iteration in the common case where the step 1 is accepted. Their initial matrix is the
// stiffness preconditioner (Stiffness_preconditioner.h), recomputed at every iterate; the
// inverse Hessian is applied in three passes over the vertices (Lbfgs_inverse_hessian.h).
//
// Each iteration:
//  1. the active set: the vertices on the boundary of their bound that -g pushes outwards;
//  2. the direction d = -H g restricted to that face, H the L-BFGS inverse Hessian of the last
//     `memory` steps with H0 = gamma K^-1, K the vertices' stiffness and gamma fitted to the
//     newest pair (d = -K^-1 g restricted when H gives no descent direction, or has no pairs);
//  3. each vertex's move shortened to a tenth of its reach, so that no triangle flips or
//     collapses;
//  4. backtracking along P(x + t d) from t = 1 (d scaled by the last accepted step along
//     -K^-1 g when H has no pairs) until E(y) < E(x) + lambda <g, y - x>
//     (Projected_line_search).
// If that search fails, the pairs are dropped and the iteration is redone along the
// projected gradient; if that fails too, x is stationary up to rounding. Every accepted point
// lies in the feasible set and has a lower energy than the one before.
//
// The energy is an Objective (see Projected_line_search.h), Fairing_objective by default.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LBFGS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LBFGS_H

#include <CGAL/assertions.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Active_set.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Lbfgs_inverse_hessian.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Projected_line_search.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_report.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Stiffness_preconditioner.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Stopping_rule.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Surface_motion.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Bound, typename Objective = Fairing_objective>
class Projected_lbfgs
{
public:
  // lambda of the sufficient decrease condition
  static constexpr double sufficient_decrease = 1e-4;
  // The longest move of a vertex in one step, relative to its reach (Stiffness_and_reach). A tenth
  // changes a triangle's area vector N by at most 0.33 |N| in a step (0.3 to first order, as
  // moving vertex v by d adds d x e with |e| h_v = |N|, and 0.03 to second), so that no step
  // flips or collapses it; at a half, steps changed some by 1.5 |N|. On the benchmark bunnies
  // (75 k to 1.2 M triangles, epsilon 0.25 h and 1 h), a tenth also reaches 1.02 E* in 5-26 %
  // fewer iterations than a half, with nearly no rejected step; a fiftieth stalls.
  static constexpr double reach_fraction = 0.1;

  Projected_lbfgs(const Bound& bound, Objective& energy) : m_bound(bound), m_energy(energy) {}

  // Fairs X, feasible on entry, in place. `callback(iteration, energy)` returning false
  // cancels.
  template <typename Callback>
  Solver_report run(Points& X, const Solver_options& options, const Callback& callback)
  {
    Solver_report report;
    // The line search counts over all runs: this one's are those from here.
    const std::size_t evaluations_before = m_search.evaluations();
    double E = m_energy.value_and_gradient(X, m_G, &m_scales);
    Stopping_rule history(options);
    history.push(E);
    std::optional<Surface_motion> motion;
    if(options.remaining_motion > 0)
    {
      CGAL_precondition(options.motion_window > 0);
      motion.emplace();
      motion->end_window(m_bound, X);
    }
    // The first step moves the vertex of largest scaled gradient by epsilon.
    precondition(m_G, m_D);
    const double largest_step = m_D.rowwise().norm().maxCoeff();
    double t_gradient = largest_step > 0 ? m_bound.largest_size() / largest_step : 0;
    m_H.clear();

    while(report.iterations < options.max_iterations)
    {
      if(!(E > 0) || !(t_gradient > 0))
      {
        report.status = Constrained_fairing_status::CONVERGED;
        break;
      }
      const double slope = find_direction(X, t_gradient);
      const auto sufficient = [&](double e, const Points& Y) {
        return e < E + sufficient_decrease * dot_with_difference(m_G, Y, X, m_partial);
      };
      Projected_line_search::Accepted accepted{m_X};
      if(!m_search.backtrack(X, m_D, 1., E, slope, m_bound, m_energy, sufficient, accepted, m_G_next, m_scales_next))
      {
        if(m_H.number_of_pairs() > 0)
        {
          m_H.clear(); // the pairs misled: redo the iteration along the projected gradient
          continue;
        }
        report.status = Constrained_fairing_status::CONVERGED; // stationary up to rounding
        break;
      }
      if(m_H.number_of_pairs() == 0)
        t_gradient *= accepted.step;
      m_H.add_pair(X, m_X, m_G, m_G_next);
      X.swap(m_X);
      m_G.swap(m_G_next);
      m_scales.swap(m_scales_next);
      E = accepted.energy;
      if(motion && (report.iterations + 1) % options.motion_window == 0)
        motion->end_window(m_bound, X);
      if(!history.next_iteration(E, callback, report, !motion || motion->has_settled(options.remaining_motion)))
        break;
    }
    report.final_energy = E;
    report.energy_evaluations = m_search.evaluations() - evaluations_before + 1;
    // A run starts with no pairs: their memory, nearly half the solver's, is returned for what
    // runs between two runs (fold repair's tests).
    m_H.release();
    return report;
  }

private:
  // The direction m_D at X, restricted to the faces of the active bounds, and its slope: the
  // quasi-Newton pairs' if it descends, else (the pairs dropped) the projected gradient scaled
  // by the inverse stiffness and the gradient step t_gradient.
  double find_direction(const Points& X, double t_gradient)
  {
    m_active.compute(m_bound, X, m_G);
    double slope = 0;
    const auto write_restricted_negative_gradient = [&](Points& D, std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        point(D, i) = -point(m_G, i);
      m_active.restrict_range(D, begin, end);
    };
    if(m_H.number_of_pairs() > 0 && m_H.start(m_D, m_scales.stiffness, write_restricted_negative_gradient))
      slope = finish_direction([&](std::size_t begin, std::size_t end) {
        m_H.finish_rows(m_D, begin, end);
        m_active.restrict_range(m_D, begin, end);
      });
    if(m_H.number_of_pairs() == 0 || !(slope < 0))
    {
      m_H.clear();
      m_D.resize(m_G.rows(), 3);
      parallel_for_blocks(static_cast<std::size_t>(m_G.rows()), [&](std::size_t begin, std::size_t end, std::size_t) {
        write_restricted_negative_gradient(m_D, begin, end);
      });
      apply_inverse_stiffness(m_scales, m_D, m_D, t_gradient);
      slope = finish_direction([](std::size_t, std::size_t) {});
    }
    return slope;
  }

  // Calls `rows(begin, end)` on each block of D (the direction's last steps), shortens the
  // displacement of each vertex to at most `reach_fraction` of its reach, and returns the slope
  // <D, G>, in one pass. Why the reach: then no step can flip or collapse a triangle (see
  // reach_fraction), and the limit is a trust region per vertex, short where triangles
  // degenerate and long where they have room. Without it, the energy's pull towards slivers (see
  // the user manual) makes the quasi-Newton step overshoot on a few vertices at nearly every
  // iteration, and that one vertex gets the whole step rejected.
  template <typename Rows>
  double finish_direction(const Rows& rows)
  {
    return parallel_sum(static_cast<std::size_t>(m_D.rows()), m_partial, [&](std::size_t begin, std::size_t end) {
      rows(begin, end);
      for(std::size_t i = begin; i < end; ++i)
      {
        const double length = point(m_D, i).norm(), limit = reach_fraction * m_scales.reach[static_cast<Eigen::Index>(i)];
        if(length > limit)
          point(m_D, i) *= limit / length;
      }
      return dot_rows(m_D, m_G, begin, end);
    });
  }

  template <typename R>
  void precondition(const R& r, Points& D) const
  {
    apply_inverse_stiffness(m_scales, r, D);
  }

  const Bound& m_bound;
  Objective& m_energy;
  Active_set<Bound> m_active;
  Projected_line_search m_search;
  // gradient, direction, next point and its gradient
  Points m_G, m_D, m_X, m_G_next;
  Stiffness_and_reach m_scales, m_scales_next; // at the iterate and at the next point
  Lbfgs_inverse_hessian m_H;
  std::vector<double> m_partial;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LBFGS_H
