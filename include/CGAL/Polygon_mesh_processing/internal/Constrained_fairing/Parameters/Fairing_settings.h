// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a call asks besides its per-vertex maps (Vertex_maps.h), as plain values: the method, the
// objective, the solver's options, the bound's shape, and the weights of the terms of a
// multi-label surface. Every default lives here and only here, with why it was chosen. The
// public functions fill these from their named parameters once (read_named_parameters.h, through
// the table of Named_settings.h), and nothing below them sees a named parameter.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_SETTINGS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_SETTINGS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Solver_options.h>

#include <array>
#include <cstddef>
#include <limits>
#include <optional>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The accurate objective's fidelity weight, chosen on the benchmark fairing_accuracy over its
// whole set of meshes and noise levels (the user manual gives the alternatives' figures). Its
// anchor is made by Fidelity_anchor.h.
constexpr double default_fidelity_weight = 1e4;

// The weight of the barrier against slivers (Sliver_barrier.h), per triangle: at 1, a needle of
// 1.5 degrees costs 0.92, about as much as a right-angle bend between two equilateral triangles
// (0.87). On the benchmark fairing_accuracy, weights 0.5, 1 and 2 gave the same distance to the
// truth, normals and energies; the smallest angle over the set was 1.7, 1.8 and 2.2 degrees
// (accurate objective) and 2.3, 2.6 and 2.7 (fairest).
constexpr double default_sliver_barrier_weight = 1;

// The quality under which a triangle of a mesh is a sliver to the barrier: sqrt(3) sin(3
// degrees), within 0.2 % the quality of an isosceles needle of apex angle 3 degrees
// (Sliver_barrier::threshold_of_angle()).
constexpr double default_sliver_threshold = 0.0906485352754803;

// The needles the barrier against slivers pushes back on a multi-label surface, by their angle in
// degrees (3 on a mesh). Surface nets start from good triangles (45 degrees at least on cubic
// voxels, 18 on 1 x 1 x 3), and users mesh their surfaces for simulation. On the benchmark's
// balls (radii 24 and 17.3 voxels, cubic and 1 x 1 x 3) and three maps of 10 Voronoi labels
// (96^3), the smallest angle was 2.6 to 3.0 degrees with 3, 4.5 to 4.9 with 5 and 5.5 to 5.9
// with 6; the RMS distance to the true interfaces rose by 1 to 21 % from 3 to 6. With weight 0.3
// instead of 1 the Voronoi maps kept angles of 4.7 degrees.
constexpr double default_interface_sliver_angle = 6;

// The barrier against folds of a multi-label surface (Fold_barrier.h): its weight per hinge, and
// the angle between a hinge's normals from which the hinge pays, in degrees. On Debian's nine
// atlases, weight 1 left folds on seven; 3 and 10 on two (those folded from the smoothed start),
// 3 in the fewest evaluations; 45 degrees cost evaluations, 75 let a few turn over (design notes).
constexpr double interface_fold_weight = 3;
constexpr double interface_fold_angle = 60;

// The smallest angle, in degrees, under which the repair after the descent pulls a triangle of a
// multi-label surface back towards its start (Crossing_repair.h), unless it started smaller.
// Where the bounds and the junction lines hold a needle against the barrier, the descent leaves
// it between 4 and 6 degrees on the atlases of label_map_topology. Pulling back the triangles
// under 5 degrees raised their energy by 0.2 to 1.1 %; pulling back every triangle of a quality
// under a 6-degree needle's, 3.5 to 11 times (design notes).
constexpr double interface_repair_angle = 5;
static_assert(interface_repair_angle < default_interface_sliver_angle,
              "the repair takes over where the barrier leaves needles, under its angle");

// The weight of the curves' term (Curve_bending.h: a multi-label surface's junction lines, a
// mesh's creases), per inner point of a curve, against the bending energy's hinges.
constexpr double default_curve_weight = 1;

// The weight of the labels' volumes of a multi-label surface (Label_volumes.h), per point,
// against the bending energy's hinges. Held exactly, from 1 to 30 the phantoms of
// benchmark/label_phantoms came out alike (4.60 to 4.67 times closer to the truth than the raw
// nets); above 1 the smallest angle fell on generated worst cases and atlases (random voxels of
// three labels: 2.9 degrees with no term, 3.3 at 1, 0.35 at 3). A label thinner than the mean
// edge length is charged for each of its points' three hinges (Label_volumes.h).
constexpr double default_label_volume_weight = 1;

// The stopping rule of each method when the user sets none: the quasi-Newton method's energy
// keeps decreasing in small, uneven steps, with plateaus of tens of iterations, long after the
// noise is gone, so it is judged over 50 iterations and against a smaller threshold, and it
// stops only once the decrease still to come, extrapolated from the last two windows, is at
// most 1 % of the energy (Stopping_rule.h): on large meshes each iteration gains less, and the
// threshold alone stopped the call early there. On energy traces of the noisy bunny with no
// stopping rule (2000 iterations at 75 k, 300 k and 1.2 M triangles, 1000 at 4.8 M and 19.3 M),
// 1 % stops within 1.5, 1.8 and 0.8 % of the energy of 1000 iterations up to 1.2 M, and runs on
// at 4.8 M and 19.3 M, where the threshold alone stopped 2.9 and 7.7 % above it (after 704 and
// 264 iterations; the smallest extrapolated remainder while the threshold held was 1.9 and
// 1.5 %, so 2 % would have stopped at 19.3 M). Where the vertices move along the normals, it
// also waits until the surface's motion still to come, extrapolated from its last two windows of
// 25 iterations, is at most 0.5 % of epsilon, RMS (Surface_motion.h): there the energy's rule
// stopped at its floor of 100 iterations (105 at 1.2 M), where three times as many still moved
// the surface by 1.23 % of epsilon at 1.2 M triangles; the extrapolation came within a factor of
// 1.4 of the motion that followed, hence half the 1 % asked. It starts from a smoothed input
// (Smoothed_start.h).
// The paper's methods keep the rule they were first built with, at most 200 iterations and
// 1e-3 over the last 3, untuned: they are there to be compared with, and the quasi-Newton
// method reaches sooner the lowest energy they reach in 500 iterations with no stopping rule
// (benchmark/results/README.md, "Speed against the paper's methods"). They start from the
// input, as in the paper; the remainder and the motion were measured for the quasi-Newton
// method only. The Newton step makes one conjugate gradient iteration: after 500 steps, 3 and 10
// gained under 1.2 % of the energy for 2.5 and 6.4 times the time (doc/design_notes.md,
// "Conjugate gradient iterations per Newton step"); the projected gradient method makes Cauchy
// steps only, the paper's explicit method.
// A point set's neighbours per point (`number_of_neighbors`), for its normals, its tangent fans
// and the accurate objective's jet fit (Point_sets/): chosen on the held-out camel of
// benchmark/point_set_fairing (20,000 points, 1 % and 2 % noise) among 16, 24, 32 and 48, where
// 32 gave the accurate objective's points closest to the truth at both levels (0.48 and 0.44
// sigma, against 0.54 and 0.59 with 16, 0.61 and 0.47 with 48) and the fairest within 3 % of the
// best (doc/design_notes.md, "Point sets").
constexpr std::size_t default_number_of_neighbors = 32;

inline Solver_options default_options(Constrained_fairing_method method)
{
  Solver_options options;
  if(method == Constrained_fairing_method::QUASI_NEWTON)
  {
    options.threshold = 1.25e-4;
    options.window = 50;
    options.remaining_fraction = 0.01;
    options.max_iterations = 1000;
    options.smoothing_steps = 16;
    options.remaining_motion = 0.005;
    options.motion_window = 25;
  }
  else
  {
    options.threshold = 1e-3;
    options.window = 3;
    options.max_iterations = 200;
  }
  options.cg_iterations = 1;
  options.cauchy_steps_only = method == Constrained_fairing_method::PROJECTED_GRADIENT;
  return options;
}

struct Fairing_settings
{
  explicit Fairing_settings(Constrained_fairing_method m = Constrained_fairing_method::QUASI_NEWTON)
    : method(m), options(default_options(m))
  {}

  // The accurate objective: a fidelity term of weight `fidelity_weight` (> 0) is added.
  bool is_accurate() const { return objective == Constrained_fairing_objective::ACCURATE && fidelity_weight > 0; }

  // Whether the vertices slide along the surface, or move along the normals of the smoothed
  // start (Normal_offsets.h). Unless the user said, they move along the normals only with the
  // quasi-Newton method, the ball and the fairest objective: a ball of noise leaves the surface
  // accurate along its normals, and there the sliding only lowers the energy at the expense of
  // the distance to the true surface, while the vertices of voxel terraces, in boxes, must slide
  // to reach it, and the accurate objective's fidelity term holds them where the sliding helps
  // it a little (doc/design_notes.md, "Normal offsets"); the paper's methods are the paper's.
  bool slides(bool box) const
  {
    return tangential_motion ? *tangential_motion
                             : method != Constrained_fairing_method::QUASI_NEWTON || box || is_accurate();
  }

  // A box bound: asked for, or implied by a box parameter (a uniform half-extents or a map).
  bool is_box() const { return deviation_bound == Deviation_bound::BOX || has_box_parameter; }

  // The box half-extents of every vertex without its own, before its tolerance caps them:
  // infinite (the tolerance alone) unless given.
  std::array<double, 3> uniform_box_half_extents() const
  {
    constexpr double none = std::numeric_limits<double>::infinity();
    return box_half_extents ? *box_half_extents : std::array<double, 3>{none, none, none};
  }

  Constrained_fairing_method method;
  Solver_options options;
  Constrained_fairing_objective objective = Constrained_fairing_objective::FAIREST;
  double fidelity_weight = default_fidelity_weight;
  double sliver_barrier_weight = default_sliver_barrier_weight;
  double sliver_threshold = default_sliver_threshold;
  double interface_sliver_angle = default_interface_sliver_angle;
  double curve_weight = default_curve_weight;
  double label_volume_weight = default_label_volume_weight;
  // The dihedral angle, in degrees, over which the feature detection (Feature_edges.h) marks an
  // edge as a crease; unset, only the edges the user marks are.
  std::optional<double> feature_angle;
  // A point set's neighbours per point.
  std::size_t number_of_neighbors = default_number_of_neighbors;
  // Whether the vertices may also slide along the surface, as the user set it; unset, they do
  // (see slides()).
  std::optional<bool> tangential_motion;
  // The shape the user named, if any; whether a box parameter is given; the uniform box
  // half-extents, if given.
  std::optional<Deviation_bound> deviation_bound;
  bool has_box_parameter = false;
  std::optional<std::array<double, 3> > box_half_extents;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_SETTINGS_H
