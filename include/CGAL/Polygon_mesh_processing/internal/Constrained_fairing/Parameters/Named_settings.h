// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The settings a user sets by name (Fairing_settings.h), as one table of names, named parameters
// and fields.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NAMED_SETTINGS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NAMED_SETTINGS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The settings a user sets by name, each with its name in the front ends (the Python module's
// keyword, the batch's option), its named parameter and its tag, and its field: the one table
// from which read_fairing_settings() reads the named parameters and the Python binding its
// options and defaults, its keywords' conversions being Python's (test_defaults.py checks the
// binding's signature, conversions and docstrings against it). The method is not in it: it
// chooses the others' defaults (default_options()).
template <typename Settings, typename F>
void for_each_named_setting(Settings& settings, const F& f)
{
  f("max_iterations", "number_of_iterations", internal_np::number_of_iterations, settings.options.max_iterations);
  f("energy_decrease_threshold", "energy_decrease_threshold", energy_decrease_threshold, settings.options.threshold);
  f("initial_smoothing_steps", "initial_smoothing_steps", initial_smoothing_steps, settings.options.smoothing_steps);
  f("conjugate_gradient_iterations", "conjugate_gradient_iterations", conjugate_gradient_iterations,
    settings.options.cg_iterations);
  f("objective", "fairing_objective", fairing_objective, settings.objective);
  f("fidelity_weight", "fidelity_weight", fidelity_weight, settings.fidelity_weight);
  f("sliver_barrier_weight", "sliver_barrier_weight", sliver_barrier_weight, settings.sliver_barrier_weight);
  f("tangential_motion", "tangential_motion", tangential_motion, settings.tangential_motion);
  f("feature_angle", "feature_angle", feature_angle, settings.feature_angle);
}

// The tag of the named parameter fairing_settings() (Constrained_fairing_settings.h) that gives
// all the settings at once, the method included: the settings of the table that the other named
// parameters give override its fields (fairing_method does not, as it would reset the others'
// defaults). The front ends, whose users set them at run time, call the public functions with it.
enum fairing_settings_t { fairing_settings };

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NAMED_SETTINGS_H
