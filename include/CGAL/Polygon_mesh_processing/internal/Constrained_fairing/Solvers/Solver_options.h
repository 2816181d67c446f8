// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a solver is asked: how many iterations at most, its stopping rule's threshold and
// window, and the options of the paper's methods. The values here are the paper's methods';
// Fairing_settings.h holds the defaults of each method.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_OPTIONS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_OPTIONS_H

#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Solver_options
{
  std::size_t max_iterations = 200;
  // Stop when the energy decreased by less than `threshold` relatively per iteration, on
  // average over the last `window` iterations.
  double threshold = 1e-3;
  std::size_t window = 3;
  // And, if positive, when the decrease still to come, extrapolated from the last two windows,
  // is at most this fraction of the energy (Stopping_rule.h).
  double remaining_fraction = 0;
  // And, if positive, where the vertices move along normals only, when the surface's motion
  // still to come, extrapolated from its last two windows of `motion_window` iterations, is at
  // most this fraction of the bounds' sizes, RMS (Surface_motion.h).
  double remaining_motion = 0;
  std::size_t motion_window = 25;
  // Newton method: the largest number of conjugate gradient iterations per step (at least one
  // is made).
  std::size_t cg_iterations = 1;
  // Projected gradient method: Cauchy steps only.
  bool cauchy_steps_only = false;
  // Steps of projected Taubin smoothing before the first iteration (Smoothed_start.h).
  std::size_t smoothing_steps = 0;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_OPTIONS_H
