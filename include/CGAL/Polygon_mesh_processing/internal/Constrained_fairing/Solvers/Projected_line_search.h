// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The search for a good point on a projected ray r(t) = P(x + t v) (Section 4). The accepted
// point goes to a buffer the caller owns (swapped in, so that no call allocates once the
// buffers have their sizes). Whatever the caller's condition, an accepted point's energy is
// below E0, the energy at x: with the projection, or rounding at extreme coordinates, a
// sufficient decrease measured by the slope of the step taken can come out positive and allow
// a rise.
//  - search(): the paper's rule. From an initial guess t0 (the previous iteration's step),
//    double t while the descent condition holds, or halve it until it holds. Doubling also
//    stops as soon as the energy no longer improves on the last accepted point, so that a
//    longer step is never taken for a worse one.
//  - backtrack(): for quasi-Newton directions, whose natural step is 1: shorten t from t0
//    until the condition holds, evaluating the gradient (and the vertex scales) with the energy
//    since the accepted point needs them next.
//
// The objective: the solvers (Projected_lbfgs.h, Active_set_newton.h) and this search are
// templated on the function they minimize over n vertices, an `Objective` (the fairing's is
// Fairing_objective.h; a quadratic with a known minimizer tests them). They call only:
//  - double value(const Points& X): its value at X (n x 3);
//  - double value_and_gradient(const Points& X, Points& G, Stiffness_and_reach* scales): its value,
//    with its gradient written to G (resized to n x 3) and, if `scales` is not null (the
//    quasi-Newton method only), scales->stiffness and scales->reach (Bending_energy.h),
//    resized to n: per vertex, a positive estimate of the Hessian's diagonal, the same for its
//    three coordinates (0 for a vertex that stays), and the length of a move known not to harm
//    (each step moves a vertex by at most Projected_lbfgs::reach_fraction of it; infinity for
//    no limit).
// Both may change the objective's buffers, so it is passed by non-const reference. The value
// must be non-negative: the solvers stop at 0 and judge a decrease relative to the value
// (Stopping_rule.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LINE_SEARCH_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LINE_SEARCH_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Projected_line_search
{
public:
  static constexpr int max_doublings = 30;
  // t0 * 2^-60 is far below any useful step: the condition cannot be met in double.
  static constexpr int max_halvings = 60;

  // What an accepted point is: written to `point`, with its energy and step.
  struct Accepted
  {
    Points& point;
    double energy = 0;
    double step = 0;
  };

  // The paper's search from t0, from x of energy E0. `holds(energy, point)` is the descent
  // condition. Returns true and fills `accepted` on success.
  template <typename Bound, typename Objective, typename Condition>
  bool search(const Points& x, double E0, const Points& v, double t0, const Bound& bound, Objective& energy,
              const Condition& holds, Accepted& accepted)
  {
    double t = t0;
    if(try_step(x, E0, v, t, bound, energy, holds))
    {
      accept(t, accepted);
      for(int k = 0; k < max_doublings; ++k)
      {
        t *= 2;
        if(!try_step(x, E0, v, t, bound, energy, holds) || !(m_trial_energy < accepted.energy))
          break;
        accept(t, accepted);
      }
      return true;
    }
    for(int k = 0; k < max_halvings; ++k)
    {
      t /= 2;
      if(try_step(x, E0, v, t, bound, energy, holds))
      {
        accept(t, accepted);
        return true;
      }
    }
    return false;
  }

  // From t0 only down, for a direction v along which the energy E0 at x has the slope
  // <g, v>: each rejected step t is followed by the minimizer of the quadratic through E0,
  // that slope and the rejected energy, kept within [t/10, t/2]. The trial points are written
  // straight to `accepted.point`, with the gradient and the vertex scales
  // (the objective's value_and_gradient()) to G and scales, so that the accepted one needs no
  // copy; on failure, all three hold the last rejected trial.
  template <typename Bound, typename Objective, typename Condition>
  bool backtrack(const Points& x, const Points& v, double t0, double E0, double slope, const Bound& bound,
                 Objective& energy, const Condition& holds, Accepted& accepted, Points& G, Stiffness_and_reach& scales)
  {
    double t = t0;
    for(int k = 0; k < max_halvings; ++k)
    {
      if(projected_step_to(accepted.point, x, t, v, bound))
      {
        ++m_evaluations;
        const double e = energy.value_and_gradient(accepted.point, G, &scales);
        if(e < E0 && holds(e, accepted.point))
        {
          accepted.energy = e;
          accepted.step = t;
          return true;
        }
        const double curvature = e - E0 - slope * t;
        const double t_model = curvature > 0 ? -slope * t * t / (2 * curvature) : 0;
        t = (std::min)((std::max)(t_model, 0.1 * t), 0.5 * t);
      }
      else
        t /= 2;
    }
    return false;
  }

  // Energy evaluations so far, with or without the gradient.
  std::size_t evaluations() const { return m_evaluations; }

private:
  template <typename Bound, typename Objective, typename Condition>
  bool try_step(const Points& x, double E0, const Points& v, double t, const Bound& bound, Objective& energy,
                const Condition& holds)
  {
    if(!projected_step_to(m_trial, x, t, v, bound)) // a step so long that it overflows is no candidate
      return false;
    ++m_evaluations;
    m_trial_energy = energy.value(m_trial);
    return m_trial_energy < E0 && holds(m_trial_energy, m_trial);
  }

  // y = P(x + t v) in one pass, each block projected as soon as it is computed; false if a
  // coordinate of x + t v is not finite.
  template <typename Bound>
  bool projected_step_to(Points& y, const Points& x, double t, const Points& v, const Bound& bound)
  {
    y.resize(x.rows(), 3);
    const double finite = parallel_sum(static_cast<std::size_t>(x.rows()), m_partial, [&](std::size_t begin, std::size_t end) {
      bool all = true;
      for(std::size_t i = begin; i < end; ++i)
      {
        point(y, i) = point(x, i) + t * point(v, i);
        all = all && point(y, i).allFinite();
      }
      if(!all)
        return 0.;
      bound.project_range(y, begin, end);
      return 1.;
    });
    return finite == double(m_partial.size());
  }

  void accept(double t, Accepted& accepted)
  {
    std::swap(accepted.point, m_trial);
    accepted.energy = m_trial_energy;
    accepted.step = t;
  }

  Points m_trial;
  std::vector<double> m_partial;
  double m_trial_energy = 0;
  std::size_t m_evaluations = 0;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LINE_SEARCH_H
