// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stopping rule shared by the solvers: the energies of the iterations so far, and whether
// the last `window` of them decreased by less than `threshold` relatively on average and, where
// `remaining_fraction` is set, whether what is left to gain is that fraction of the energy at
// most.
//
// Why the second test: a small decrease alone does not tell convergence from slow progress. On
// large meshes each iteration gains less, so a run can fall under the threshold long before it
// is done (the figures are with the defaults, in Fairing_settings.h). What is left is estimated
// from the last two windows: if each window's decrease were the ratio q of the one before, as
// it is in linear convergence, d1 q / (1 - q) would remain after a window that gained d1.
// Steady progress, however slow, has q near or above 1 and does not stop the run; progress that
// fades does.
//
// Where the shape's motion is judged too (Surface_motion.h), the solver tells whether it has
// settled, and the rule stops only when both have.
//
// Only the last two windows are kept (a ring of 2 window + 1 energies), so that the rule's memory
// does not grow with the number of iterations allowed or run.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STOPPING_RULE_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STOPPING_RULE_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_report.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Whether what is left, extrapolated from a window that gained `last` after one that gained
// `previous` (q = last / previous each window, as in linear convergence: last q / (1 - q)), is
// at most `at_most`. Steady progress, q near or above 1, is never small.
inline bool remainder_is_small(double last, double previous, double at_most)
{
  const double q = last / previous;
  return q < 1 && last * q / (1 - q) <= at_most;
}

class Stopping_rule
{
public:
  explicit Stopping_rule(const Solver_options& options)
    : m_window(options.window), m_threshold(options.threshold), m_remaining_fraction(options.remaining_fraction),
      m_energies(2 * options.window + 1)
  {
  }

  void push(double energy)
  {
    m_energies[m_count % m_energies.size()] = energy;
    ++m_count;
  }

  // Counts an iteration that reached `energy`, tells the callback, and returns false, with
  // the status set, when the run stops there: cancelled by the callback, or stalled.
  // `settled`: whether the shape has stopped moving too, where that is judged
  // (Surface_motion.h).
  template <typename Callback>
  bool next_iteration(double energy, const Callback& callback, Solver_report& report, bool settled = true)
  {
    push(energy);
    ++report.iterations;
    if(!callback(report.iterations, energy))
    {
      report.status = Constrained_fairing_status::CANCELLED;
      return false;
    }
    if(settled && has_stalled())
    {
      report.status = Constrained_fairing_status::CONVERGED;
      return false;
    }
    return true;
  }

  bool has_stalled() const
  {
    if(m_count <= m_window)
      return false;
    const double newest = ago(0), before = ago(m_window);
    const double last = before - newest;
    if(!(last <= double(m_window) * m_threshold * before))
      return false;
    if(!(m_remaining_fraction > 0))
      return true;
    if(!(last > 0))
      return true; // no decrease over a whole window: stationary
    if(m_count <= 2 * m_window)
      return false;
    return remainder_is_small(last, ago(2 * m_window) - before, m_remaining_fraction * newest);
  }

private:
  // The energy pushed k pushes before the newest (k <= 2 window).
  double ago(std::size_t k) const { return m_energies[(m_count - 1 - k) % m_energies.size()]; }

  std::size_t m_window;
  double m_threshold;
  double m_remaining_fraction;
  std::vector<double> m_energies; // a ring: push number c at c mod its size
  std::size_t m_count = 0;        // pushes so far
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STOPPING_RULE_H
