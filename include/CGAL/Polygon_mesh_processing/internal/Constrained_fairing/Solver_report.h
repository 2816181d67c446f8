// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a solver is asked (its options, the callback it calls after each iteration) and what
// it answers (its report), which the driver turns into the public result once.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_REPORT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_REPORT_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The iteration callback, a callable bool(std::size_t, double), held by reference: the solvers
// take this one type, so that they are compiled once whatever callbacks a program passes.
class Iteration_callback
{
public:
  template <typename Callback>
  Iteration_callback(const Callback& callback)
    : m_callback(&callback), m_call([](const void* f, std::size_t iteration, double energy) {
        return bool((*static_cast<const Callback*>(f))(iteration, energy));
      })
  {}

  bool operator()(std::size_t iteration, double energy) const { return m_call(m_callback, iteration, energy); }

private:
  const void* m_callback;
  bool (*m_call)(const void*, std::size_t, double);
};

struct Solver_options
{
  std::size_t max_iterations = 200;
  // Stop when the energy decreased by less than `threshold` relatively per iteration, on
  // average over the last `window` iterations.
  double threshold = 1e-3;
  std::size_t window = 3;
  // Newton method: the largest number of conjugate gradient iterations per step.
  std::size_t cg_iterations = 1;
  // Projected gradient method: Cauchy steps only.
  bool cauchy_steps_only = false;
  // Steps of projected Taubin smoothing before the first iteration (Smoothed_start.h).
  std::size_t smoothing_steps = 0;
};

struct Solver_report
{
  Constrained_fairing_status status = Constrained_fairing_status::ITERATION_LIMIT_REACHED;
  std::string message;
  std::size_t iterations = 0;
  std::size_t cg_iterations = 0;
  std::size_t energy_evaluations = 0;
  double initial_energy = 0;
  double final_energy = 0;
};

// The stopping rule shared by the solvers: the energies of the iterations so far, and
// whether the last `window` of them decreased by less than `threshold` relatively on average.
class Energy_history
{
public:
  explicit Energy_history(const Solver_options& options) : m_window(options.window), m_threshold(options.threshold)
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

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_REPORT_H
