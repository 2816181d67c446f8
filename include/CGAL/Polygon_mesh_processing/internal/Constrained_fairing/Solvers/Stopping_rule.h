// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stopping rule shared by the solvers: the energies of the iterations so far, and whether
// the last `window` of them decreased by less than `threshold` relatively on average.

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

class Stopping_rule
{
public:
  explicit Stopping_rule(const Solver_options& options) : m_window(options.window), m_threshold(options.threshold)
  {
    m_energies.reserve(options.max_iterations + 1);
  }

  void push(double energy) { m_energies.push_back(energy); }

  // Counts an iteration that reached `energy`, tells the callback, and returns false, with
  // the status set, when the run stops there: cancelled by the callback, or stalled.
  template <typename Callback>
  bool next_iteration(double energy, const Callback& callback, Solver_report& report)
  {
    push(energy);
    ++report.iterations;
    if(!callback(report.iterations, energy))
    {
      report.status = Constrained_fairing_status::CANCELLED;
      return false;
    }
    if(has_stalled())
    {
      report.status = Constrained_fairing_status::CONVERGED;
      return false;
    }
    return true;
  }

  bool has_stalled() const
  {
    if(m_energies.size() <= m_window)
      return false;
    const double before = m_energies[m_energies.size() - 1 - m_window];
    return before - m_energies.back() <= double(m_window) * m_threshold * before;
  }

private:
  std::size_t m_window;
  double m_threshold;
  std::vector<double> m_energies;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STOPPING_RULE_H
