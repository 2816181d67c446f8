// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a solver is asked: how many iterations at most, its stopping rule's threshold and
// window, and the options of the paper's methods. Left as it is built it asks for nothing (no
// iteration, every rule and option off): the defaults of a call, each method's with its reason,
// are default_options() of Fairing_settings.h.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_OPTIONS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SOLVER_OPTIONS_H

#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Solver_options
{
  std::size_t max_iterations = 0;
  // Stop when the energy decreased by less than `threshold` relatively per iteration, on
  // average over the last `window` iterations.
  double threshold = 0;
  std::size_t window = 0;
  // And, if positive, when the decrease still to come, extrapolated from the last two windows,
  // is at most this fraction of the energy (Stopping_rule.h).
  double remaining_fraction = 0;
  // And, if positive, where the vertices move along normals only, when the surface's motion
  // still to come, extrapolated from its last two windows of `motion_window` iterations, is at
  // most this fraction of the bounds' sizes, RMS (Surface_motion.h).
  double remaining_motion = 0;
  std::size_t motion_window = 0;
  // Newton method: the largest number of conjugate gradient iterations per step (at least one
  // is made).
  std::size_t cg_iterations = 0;
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
