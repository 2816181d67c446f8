// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The search for a good point on a projected ray r(t) = P(x + t v) (Section 4): from an
// initial guess t0 (the previous iteration's step), double t while the descent condition
// holds, or halve it until it holds. Doubling also stops as soon as the energy no longer
// improves on the last accepted point, so that a longer step is never taken for a worse one.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LINE_SEARCH_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LINE_SEARCH_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Feasible_set.h>

#include <utility>

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

  // Searches r(t) from t0. `holds(energy, point)` is the descent condition. On success,
  // returns true; `step()`, `energy()` and `point()` then describe the accepted point.
  template <typename Condition>
  bool run(const Points& x, const Points& v, double t0, const Feasible_set& omega,
           Bending_energy& energy, const Condition& holds)
  {
    double t = t0;
    if(try_step(x, v, t, omega, energy, holds))
    {
      accept(t);
      for(int k = 0; k < max_doublings; ++k)
      {
        t *= 2;
        if(!try_step(x, v, t, omega, energy, holds) || !(m_trial_energy < m_energy))
          break;
        accept(t);
      }
      return true;
    }
    for(int k = 0; k < max_halvings; ++k)
    {
      t /= 2;
      if(try_step(x, v, t, omega, energy, holds))
      {
        accept(t);
        return true;
      }
    }
    return false;
  }

  double step() const { return m_step; }
  double energy() const { return m_energy; }
  const Points& point() const { return m_point; }
  Points& point() { return m_point; }

private:
  template <typename Condition>
  bool try_step(const Points& x, const Points& v, double t, const Feasible_set& omega,
                Bending_energy& energy, const Condition& holds)
  {
    m_trial.noalias() = x + t * v;
    if(!m_trial.allFinite()) // a step so long that it overflows is no candidate
      return false;
    omega.project(m_trial);
    m_trial_energy = energy.value(m_trial);
    return holds(m_trial_energy, m_trial);
  }

  void accept(double t)
  {
    std::swap(m_point, m_trial);
    m_energy = m_trial_energy;
    m_step = t;
  }

  Points m_trial, m_point;
  double m_trial_energy = 0, m_energy = 0, m_step = 0;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_PROJECTED_LINE_SEARCH_H
