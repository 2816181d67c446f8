// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether the default call's stopping rule stops early: its result against the surface that
// REFERENCE iterations of the same objective reach from the same input with no stopping rule.
//
//   fairing_convergence [MESH] [--level L] [--reference R] [--threads K]
//
// MESH (default: the bundled bunny) is Loop subdivided L times (default 1) and given seeded
// noise of 0.25 h, epsilon = 0.25 h, as in fairing_scaling; R defaults to 2000. Prints the CPU
// model and the threads, then for both runs the time, iterations and bending energy, and for
// the default call against the reference:
//  - the RMS distance between the two surfaces, each vertex of one to the other surface, both
//    ways, in percent of epsilon (sliding along the surface does not count);
//  - the mean angle between corresponding face normals, in degrees;
//  - the bending energy as a ratio of the reference's;
//  - the smallest triangle angle of each, and whether the bound holds in double for each.

#include "benchmark_support.h"
#include "surface_quality.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

using benchmark::Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;

int main(int argc, char* argv[])
{
  const benchmark::Arguments arguments(argc, argv);
  const benchmark::Thread_limit thread_limit(arguments);
  Mesh base;
  std::string name;
  if(!benchmark::read_base_mesh(arguments, base, name))
    return EXIT_FAILURE;
  const auto level = static_cast<unsigned int>(std::stoul(arguments.option("level", "1")));
  const auto reference_iterations = static_cast<unsigned int>(std::stoul(arguments.option("reference", "2000")));
  Mesh noisy;
  const double h = benchmark::make_noisy_case(base, level, noisy);
  const double eps = 0.25 * h;

  Mesh result = noisy, reference = noisy;
  auto start = std::chrono::steady_clock::now();
  const auto r = PMP::constrained_fairing(result, eps);
  const double seconds = benchmark::seconds_since(start);
  start = std::chrono::steady_clock::now();
  const auto r_ref = PMP::constrained_fairing(
    reference, eps, CFP::energy_decrease_threshold(0.0, CGAL::parameters::number_of_iterations(reference_iterations)));
  const double ref_seconds = benchmark::seconds_since(start);

  const benchmark::Agreement agreement = benchmark::compare(result, reference);
  const double distance_rms = agreement.distance_rms;
  const double normal_difference = agreement.normal_difference_deg;

  std::cout << benchmark::machine_description() << "\n"
            << name << " Loop subdivided " << level << " times: " << num_faces(noisy)
            << " triangles; noise and epsilon 0.25 h = " << eps << "\n"
            << std::setprecision(4) << "default call:  " << seconds << " s, " << r.number_of_iterations
            << " iterations, bending energy " << r.final_bending_energy << ", smallest angle "
            << benchmark::smallest_angle_deg(result) << " deg, bound "
            << (benchmark::ball_holds(result, noisy, eps) ? "holds" : "VIOLATED") << "\n"
            << "reference:     " << ref_seconds << " s, " << r_ref.number_of_iterations << " iterations, bending energy "
            << r_ref.final_bending_energy << ", smallest angle " << benchmark::smallest_angle_deg(reference)
            << " deg, bound " << (benchmark::ball_holds(reference, noisy, eps) ? "holds" : "VIOLATED") << "\n"
            << "against it:    surface distance RMS " << 100 * distance_rms / eps << " % of epsilon, mean normal difference "
            << normal_difference << " deg, bending energy "
            << r.final_bending_energy / r_ref.final_bending_energy << " of it\n"
            << "row: " << num_faces(noisy) << " " << r.number_of_iterations << " " << 100 * distance_rms / eps << " "
            << normal_difference << " " << r.final_bending_energy / r_ref.final_bending_energy
            << std::endl;
  return EXIT_SUCCESS;
}
