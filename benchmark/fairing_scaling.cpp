// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the default call scales, one mesh size per process so that the peak memory is that of
// one call:
//
//   fairing_scaling [MESH] [--level L] [--runs N] [--threads K] [--reference R] [--default-only 1]
//
// MESH (default: the bundled bunny, data/bunny00.off) is Loop subdivided L times (default 1; 4
// gives 19.3 M triangles) and given seeded noise of 0.25 h; epsilon = 0.25 h. K limits the
// library's threads (default: all). Prints the CPU model and the threads first; reports, all
// measured in this process, medians of N runs (default 3):
//  - the default call as a user makes it: time, iterations, energy evaluations, energy
//    (the objective, and the bending energy alone), the result's smallest angle;
//  - the same call without the barrier against slivers (sliver_barrier_weight(0)): time,
//    iterations, bending energy, smallest angle, and the time as a ratio of it;
//  - the peak resident memory of the whole process during the first call (the mesh included),
//    in bytes per triangle;
//  - where the time goes: setup (input checks, connectivity, the energy's set-up and first
//    evaluation: the call with number_of_iterations(0)), energy and gradient evaluations
//    (their count times the time of one), and the rest (directions, active sets,
//    projections);
//  - the accurate objective (fairing_objective(ACCURATE)): time and iterations;
//  - the same driver built with CGAL's flags (-frounding-math, as through CGAL::CGAL) and
//    without -frounding-math (default_call_variant.h), runs alternating: both times, their
//    ratio, and whether both gave the same points;
//  - two yardsticks on the same mesh: CGAL's smooth_shape (10 iterations, time 0.03 h^2) and
//    one CHOLMOD supernodal factorization of the cotan stiffness matrix S (when CHOLMOD is
//    found), with the default call's time as a ratio of each.
// With R > 0, also what users see, against the clean surface (the subdivided mesh before the
// noise): the RMS distance of the default call's result and its mean normal error, its
// smallest angle and the bound in double, and the same of the state that R iterations of
// sliding vertices (tangential_motion(true)) reach with no stopping rule, with the ratios of the
// two; then the honest stop: how far three times the default's iterations, the stopping rule
// off, still move its surface (RMS distance both ways, in percent of epsilon) and lower its
// energy. --default-only 1 leaves out the variants of
// the call (no barrier, accurate objective, the two builds), which on the largest meshes take
// hours. run_scaling.sh runs it over sizes and fits the growth exponent.

#include "benchmark_support.h"
#include "default_call_variant.h"
#include "surface_quality.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hilbert_order.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Thin_plate_hessian.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using benchmark::Mesh;
using benchmark::Point;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CF = PMP::internal::Constrained_fairing;

int main(int argc, char* argv[])
{
  const benchmark::Arguments arguments(argc, argv);
  const int runs = arguments.runs;
  const auto reference_iterations = static_cast<unsigned int>(std::stoul(arguments.option("reference", "0")));
  const bool default_only = arguments.option("default-only", "0") != "0";
  const benchmark::Thread_limit thread_limit(arguments);
  Mesh base;
  std::string name;
  if(!benchmark::read_base_mesh(arguments, base, name))
    return EXIT_FAILURE;
  const auto level = static_cast<unsigned int>(std::stoul(arguments.option("level", "1")));
  Mesh noisy;
  double h = 0;
  // The clean surface's points (the subdivided mesh before the noise), kept as points only so
  // that the peak memory of the first call counts no second mesh, and only where they are
  // measured against (--reference), since a user's process would not hold them.
  std::vector<Point> clean_points;
  {
    // Subdivision leaves the mesh's arrays with spare capacity; a copy holds the mesh as
    // compactly as one read from a file.
    Mesh subdivided = base;
    CGAL::Subdivision_method_3::Loop_subdivision(subdivided, CGAL::parameters::number_of_iterations(level));
    if(reference_iterations > 0)
      for(auto v : vertices(subdivided))
        clean_points.push_back(subdivided.point(v));
    // as benchmark::make_noisy_case(), which would subdivide again
    h = benchmark::mean_edge_length(subdivided);
    benchmark::add_noise(subdivided, 0.25 * h, 1);
    noisy = subdivided;
  }
  base.clear();
  const double eps = 0.25 * h;
  const double triangles = double(num_faces(noisy));
  std::vector<Point> input;
  for(auto v : vertices(noisy))
    input.push_back(noisy.point(v));
  auto restore = [&](Mesh& m) {
    for(auto v : vertices(m))
      m.point(v) = input[v.idx()];
  };

  std::cout << benchmark::machine_description() << "\n"
            << name << " Loop subdivided " << level << " times: " << num_vertices(noisy) << " vertices, "
            << num_faces(noisy) << " triangles; noise and epsilon 0.25 h = " << eps << "; medians of " << runs
            << " runs\n";

  // The first call, on the mesh itself: the peak memory of the process during a call.
  benchmark::reset_peak_memory();
  PMP::Constrained_fairing_result r = PMP::constrained_fairing(noisy, eps);
  const double peak = benchmark::peak_memory_bytes();
  const double smallest_angle = benchmark::smallest_angle_deg(noisy);
  Mesh first_result;
  if(reference_iterations > 0)
    first_result = noisy;
  restore(noisy);

  // Both calls are timed without the restoring of the points.
  const double seconds = benchmark::median_of(runs, [&] {
    const auto start = std::chrono::steady_clock::now();
    r = PMP::constrained_fairing(noisy, eps);
    const double call = benchmark::seconds_since(start);
    restore(noisy);
    return call;
  });
  PMP::Constrained_fairing_result r_plain, r_accurate;
  double plain_smallest_angle = 0, plain_seconds = 0, accurate_seconds = 0, flags_seconds = 0, no_flag_seconds = 0;
  bool same_points = true;
  if(!default_only)
  {
    plain_seconds = benchmark::median_of(runs, [&] {
      const auto start = std::chrono::steady_clock::now();
      r_plain = PMP::constrained_fairing(noisy, eps, PMP::constrained_fairing_parameters::sliver_barrier_weight(0.));
      const double seconds = benchmark::seconds_since(start);
      plain_smallest_angle = benchmark::smallest_angle_deg(noisy);
      restore(noisy);
      return seconds;
    });
    accurate_seconds = benchmark::median_of(runs, [&] {
      const auto start = std::chrono::steady_clock::now();
      r_accurate = PMP::constrained_fairing(
        noisy, eps,
        PMP::constrained_fairing_parameters::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE));
      const double seconds = benchmark::seconds_since(start);
      restore(noisy);
      return seconds;
    });

    // The two builds alternate, so that both see the machine in the same state.
    std::vector<double> with_flags, without_flag;
    std::vector<Point> with_flags_points;
    for(int run = 0; run < runs; ++run)
    {
      auto start = std::chrono::steady_clock::now();
      benchmark::default_call_with_cgal_flags(noisy, eps);
      with_flags.push_back(benchmark::seconds_since(start));
      with_flags_points.clear();
      for(auto v : vertices(noisy))
        with_flags_points.push_back(noisy.point(v));
      restore(noisy);
      start = std::chrono::steady_clock::now();
      benchmark::default_call_without_rounding_math(noisy, eps);
      without_flag.push_back(benchmark::seconds_since(start));
      for(auto v : vertices(noisy))
        same_points = same_points && noisy.point(v) == with_flags_points[v.idx()];
      restore(noisy);
    }
    const auto median = [](std::vector<double> t) {
      std::sort(t.begin(), t.end());
      return t[t.size() / 2];
    };
    flags_seconds = median(with_flags);
    no_flag_seconds = median(without_flag);
  }

  const double setup = benchmark::median_seconds(runs, [&] {
    PMP::constrained_fairing(noisy, eps, CGAL::parameters::number_of_iterations(0));
  });

  // One evaluation of the energy, its gradient and the vertex scales, as the solver makes it:
  // with the vertices in Hilbert order.
  CF::Points X0(static_cast<Eigen::Index>(num_vertices(noisy)), 3), G;
  for(auto v : vertices(noisy))
    X0.row(v.idx()) << input[v.idx()].x(), input[v.idx()].y(), input[v.idx()].z();
  const std::vector<CF::Index> rank = CF::hilbert_rank(X0);
  auto vertex_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), noisy);
  for(auto v : vertices(noisy))
  {
    put(vertex_index, v, std::size_t(rank[v.idx()]));
    X0.row(rank[v.idx()]) << input[v.idx()].x(), input[v.idx()].y(), input[v.idx()].z();
  }
  CF::Stiffness_and_reach K;
  double evaluation = 0, factorization = 0;
  {
    const CF::Hinge_mesh mesh(noisy, vertex_index);
    CF::Bending_energy energy(mesh, X0);
    evaluation = benchmark::median_seconds(std::max(runs, 5), [&] { energy.value_and_gradient(X0, G, &K); });
#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
    using Cholmod = benchmark::Cholmod_solver;
    factorization = benchmark::median_of(runs, [&] {
      CF::Thin_plate_hessian<Cholmod> S(mesh, X0, Cholmod());
      const auto start = std::chrono::steady_clock::now();
      S.factorize();
      return benchmark::seconds_since(start);
    });
#endif
  }
  const double smoothing = benchmark::median_seconds(runs, [&] {
    PMP::smooth_shape(noisy, 0.03 * h * h, CGAL::parameters::number_of_iterations(10));
    restore(noisy);
  });

  const double evaluations = double(r.number_of_energy_evaluations) * evaluation;
  std::cout << std::setprecision(4) << "default call:      " << seconds << " s, " << r.number_of_iterations
            << " iterations, " << r.number_of_energy_evaluations << " evaluations, energy " << r.initial_energy
            << " -> " << r.final_energy << " (bending " << r.final_bending_energy << "), smallest angle "
            << smallest_angle << " deg\n";
  if(!default_only)
    std::cout << "no barrier:        " << plain_seconds << " s, " << r_plain.number_of_iterations
              << " iterations, bending energy " << r_plain.final_bending_energy << ", smallest angle "
              << plain_smallest_angle << " deg; the default call takes " << seconds / plain_seconds << " of it\n";
  std::cout << "peak memory:       " << peak / (1 << 20) << " MiB, " << peak / triangles << " bytes per triangle\n"
            << "breakdown:         setup " << setup << " s, energy+gradient " << evaluations << " s ("
            << r.number_of_energy_evaluations << " x " << evaluation << " s), other " << seconds - setup - evaluations
            << " s; factorization and linear solves: none\n"
            << "smooth_shape:      " << smoothing << " s (10 iterations): the default call takes "
            << seconds / smoothing << " of it\n";
  if(!default_only)
    std::cout << "rounding math:     with CGAL's flags (-frounding-math) " << flags_seconds << " s, without "
              << no_flag_seconds << " s: " << flags_seconds / no_flag_seconds << " times; "
              << (same_points ? "the same points" : "different points") << "\n"
              << "accurate objective: " << accurate_seconds << " s, " << r_accurate.number_of_iterations
              << " iterations\n";
  if(factorization > 0)
  {
    std::cout << "CHOLMOD factor S:  " << factorization << " s: the default call takes " << seconds / factorization
              << " times it";
    if(!default_only)
      std::cout << ", the accurate objective " << accurate_seconds / factorization << " times";
    std::cout << "\n";
  }
  std::cout << "row: " << num_faces(noisy) << " " << seconds << " " << peak / triangles << " " << r.number_of_iterations
            << " " << smoothing << " " << factorization << " " << flags_seconds << " " << no_flag_seconds << std::endl;
  if(reference_iterations > 0)
  {
    // What users see, against the clean surface: the default call's result and the state that
    // R iterations of sliding vertices (tangential_motion(true), no stopping rule) reach.
    restore(noisy);
    Mesh clean = noisy;
    for(auto v : vertices(clean))
      clean.point(v) = clean_points[v.idx()];
    clean_points.clear();
    const benchmark::Clean_surface clean_surface(clean); // holds on to `clean`
    const auto start = std::chrono::steady_clock::now();
    const PMP::Constrained_fairing_result r_ref = PMP::constrained_fairing(
      noisy, eps,
      PMP::constrained_fairing_parameters::tangential_motion(
        true, PMP::constrained_fairing_parameters::energy_decrease_threshold(
                0.0, CGAL::parameters::number_of_iterations(reference_iterations))));
    const double reference_seconds = benchmark::seconds_since(start);
    Mesh input = noisy;
    restore(input);
    const benchmark::Quality q_ref = benchmark::measure(noisy, input, clean_surface, eps, r_ref.final_bending_energy);
    const benchmark::Quality q = benchmark::measure(first_result, input, clean_surface, eps, r.final_bending_energy);
    restore(noisy);
    std::cout << std::setprecision(4) << "against the clean surface: RMS distance " << 100 * q.surface_rms / eps
              << " % of epsilon, mean normal error " << q.normal_error_deg << " deg, smallest angle "
              << q.min_angle_deg << " deg, bound " << (q.ball_holds ? "holds" : "VIOLATED") << "\n"
              << "sliding vertices, " << reference_iterations << " iterations with no stopping rule ("
              << reference_seconds << " s): RMS distance " << 100 * q_ref.surface_rms / eps
              << " % of epsilon, mean normal error " << q_ref.normal_error_deg << " deg, bending energy "
              << r_ref.final_bending_energy << ", smallest angle " << q_ref.min_angle_deg << " deg\n"
              << "default against it: RMS distance " << q.surface_rms / q_ref.surface_rms << " times, normal error "
              << q.normal_error_deg / q_ref.normal_error_deg << " times, bending energy "
              << r.final_bending_energy / r_ref.final_bending_energy << " times\n"
              << "quality-row: " << num_faces(noisy) << " " << r.number_of_energy_evaluations << " "
              << 100 * q.surface_rms / eps << " " << q.normal_error_deg << " " << r.final_bending_energy << " "
              << q.min_angle_deg << " " << 100 * q_ref.surface_rms / eps << " " << q_ref.normal_error_deg << " "
              << r_ref.final_bending_energy << std::endl;

    // The honest stop: how much three times the default's iterations would still change, the
    // stopping rule off.
    const PMP::Constrained_fairing_result r_long = PMP::constrained_fairing(
      noisy, eps,
      PMP::constrained_fairing_parameters::energy_decrease_threshold(
        0.0, CGAL::parameters::number_of_iterations(3 * r.number_of_iterations)));
    const benchmark::Agreement moved = benchmark::compare(first_result, noisy);
    restore(noisy);
    std::cout << "three times the iterations (" << r_long.number_of_iterations << "): the surface moves by "
              << 100 * moved.distance_rms / eps << " % of epsilon (RMS), the energy falls by "
              << 100 * (r.final_energy - r_long.final_energy) / r.final_energy << " %" << std::endl;
  }
  return EXIT_SUCCESS;
}
