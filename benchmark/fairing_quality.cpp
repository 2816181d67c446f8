// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Judges constrained fairing the way users do, on a noisy mesh whose clean original is known:
//
//   fairing_quality [NOISY CLEAN EPS] [--runs N]
//
// For the input, the default call (ball), the accurate objective, the paper's box, the paper's
// Newton method (with CHOLMOD when available), and the default method stopped after 25 to 500
// iterations (no stopping rule), it reports (surface_quality.h): the bound as a user checks it,
// in double (Euclidean and per coordinate), the bending energy, the RMS distance of the vertices
// to the clean *surface* (sliding along the surface is harmless), the mean angle between
// corresponding face normals of result and clean mesh, the smallest triangle angle, the number
// of faces whose normal is more than 90 degrees from the clean one (folds), and the median time
// over N runs.
// Then the protocol of the paper's Table 1, at EPS and at 8 EPS: the default (quasi-Newton)
// call, and the paper's projected gradient and active set Newton methods (with 1, 3 and 10
// conjugate gradient iterations per step) stopped at its energy (iterations and seconds).
//
// Without arguments it reads the shared bunny meshes from the project's sibling folder
// shared/data (the CONSTRAINED_FAIRING_SHARED_DATA path) and says so; it skips cleanly when
// they are not there.

#include "surface_quality.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using benchmark::Clean_surface;
using benchmark::Mesh;
using benchmark::Quality;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;

void print_row(const std::string& name, const Quality& q, double seconds, std::size_t iterations)
{
  std::cout << std::left << std::setw(26) << name << std::right << std::setprecision(4) << std::setw(11)
            << q.max_distance << (q.ball_holds ? " " : "!") << std::setw(11) << q.max_coordinate
            << (q.box_holds ? " " : "!") << std::setw(10) << q.energy << std::setw(11) << q.surface_rms
            << std::setw(9) << q.normal_error_deg << std::setw(11) << q.min_angle_deg << std::setw(7) << q.folds
            << std::setw(6) << iterations << std::setw(9) << seconds << std::endl;
}

// Fairs a copy of `noisy` with the parameters `np` until the energy reaches `target` (or the
// pack's iteration cap), timed once.
template <typename NamedParameters>
std::pair<PMP::Constrained_fairing_result, double> run_until(const Mesh& noisy, double eps, double target,
                                                             const NamedParameters& np)
{
  Mesh m = noisy;
  PMP::Constrained_fairing_result r;
  const double seconds = benchmark::median_seconds(1, [&] {
    r = PMP::constrained_fairing(m, eps, CFP::iteration_callback([&](std::size_t, double e) { return e > target; }, np));
  });
  return {r, seconds};
}

void print_run(const std::string& name, const std::pair<PMP::Constrained_fairing_result, double>& run, double target,
               double baseline_seconds)
{
  const char* more = run.first.final_energy <= target ? "" : ">";
  std::cout << "  " << std::left << std::setw(28) << name << std::right << more << run.first.number_of_iterations
            << " iterations, " << more << run.second << " s (energy " << run.first.final_energy << "), time ratio to "
            << "the default " << more << run.second / baseline_seconds << "\n";
}

// The paper's Table 1: its methods stopped at the energy of the default call, with at most 2000
// (projected gradient) and 500 (Newton) iterations.
void table1_protocol(const Mesh& noisy, double eps, const PMP::Constrained_fairing_result& reference,
                     double reference_seconds)
{
  const double target = reference.final_energy;
  std::cout << "Table 1 protocol at eps = " << std::setprecision(6) << eps << ", stopped at equal energy " << target
            << ":\n"
            << "  quasi-Newton (default):     " << reference.number_of_iterations << " iterations, "
            << reference_seconds << " s\n";
  print_run("projected gradient:",
            run_until(noisy, eps, target,
                      CFP::fairing_method(PMP::Constrained_fairing_method::PROJECTED_GRADIENT,
                                          CFP::energy_decrease_threshold(0.0).number_of_iterations(2000))),
            target, reference_seconds);
  for(std::size_t cg : {1, 3, 10})
    print_run("Newton, " + std::to_string(cg) + " CG iterations:",
              run_until(noisy, eps, target,
                        CFP::conjugate_gradient_iterations(
                          cg, CFP::fairing_method(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON,
                                                  CFP::energy_decrease_threshold(0.0).number_of_iterations(500)))),
              target, reference_seconds);
  std::cout << std::endl;
}

int main(int argc, char* argv[])
{
  std::cout << benchmark::machine_description() << std::endl; // the CPU and threads of every figure below
  const benchmark::Arguments arguments(argc, argv);
  const std::vector<std::string>& args = arguments.positional;
  const int runs = arguments.runs;
  std::string noisy_file, clean_file;
  double eps = 0;
  if(args.size() >= 3)
  {
    noisy_file = args[0];
    clean_file = args[1];
    eps = std::stod(args[2]);
  }
  else
  {
    const std::string dir = CONSTRAINED_FAIRING_SHARED_DATA;
    noisy_file = dir + "/bunny00_d0.25.off";
    clean_file = dir + "/bunny00.off";
    eps = 0.0020265187067246755;
    if(!std::ifstream(noisy_file) || !std::ifstream(clean_file))
    {
      std::cout << "skipped: the shared bunny meshes are not in " << dir
                << " (give NOISY CLEAN EPS to measure other meshes)" << std::endl;
      return EXIT_SUCCESS;
    }
    std::cout << "reading the shared bunny meshes from " << dir << std::endl;
  }

  Mesh noisy, clean;
  if(!CGAL::IO::read_polygon_mesh(noisy_file, noisy) || !CGAL::IO::read_polygon_mesh(clean_file, clean) ||
     num_vertices(noisy) != num_vertices(clean) || num_faces(noisy) != num_faces(clean))
  {
    std::cerr << "error: cannot read two meshes of the same connectivity from " << noisy_file << " and "
              << clean_file << std::endl;
    return EXIT_FAILURE;
  }
  const Clean_surface clean_surface(clean);

  std::cout << noisy_file << ": " << num_vertices(noisy) << " vertices, " << num_faces(noisy)
            << " faces; eps = " << std::setprecision(17) << eps << "; median of " << runs << " runs\n\n";
  std::cout << std::left << std::setw(26) << "mode" << std::right << std::setw(12) << "max |p-p0|" << std::setw(12)
            << "max coord" << std::setw(10) << "energy" << std::setw(11) << "surf RMS" << std::setw(9) << "normal"
            << std::setw(11) << "min ang" << std::setw(7) << "folds" << std::setw(6) << "it" << std::setw(9) << "s"
            << "\n";

  Mesh untouched = noisy;
  const double input_energy =
    PMP::constrained_fairing(untouched, eps, CGAL::parameters::number_of_iterations(0)).final_bending_energy;
  print_row("input", benchmark::measure(noisy, noisy, clean_surface, eps, input_energy), 0, 0);

  auto run_mode = [&](const std::string& name, auto&& call, bool print = true) {
    Mesh result;
    PMP::Constrained_fairing_result r;
    const double seconds = benchmark::median_seconds(runs, [&] {
      result = noisy;
      r = call(result);
    });
    if(print)
      print_row(name, benchmark::measure(result, noisy, clean_surface, eps, r.final_bending_energy), seconds, r.number_of_iterations);
    return std::make_pair(r, seconds);
  };

  const auto reference = run_mode("ball (default call)", [&](Mesh& m) { return PMP::constrained_fairing(m, eps); });
  run_mode("ball, accurate objective", [&](Mesh& m) {
    return PMP::constrained_fairing(m, eps, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE));
  });
  run_mode("box", [&](Mesh& m) {
    return PMP::constrained_fairing(m, eps, CFP::deviation_bound(PMP::Deviation_bound::BOX));
  });
#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
  using Cholmod = benchmark::Cholmod_solver;
  run_mode("ball, Newton (CHOLMOD)", [&](Mesh& m) {
    return PMP::constrained_fairing(m, eps,
                                    CFP::fairing_method(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON,
                                                        CGAL::parameters::sparse_linear_solver(Cholmod())));
  });
#else
  run_mode("ball, Newton", [&](Mesh& m) {
    return PMP::constrained_fairing(m, eps, CFP::fairing_method(PMP::Constrained_fairing_method::ACTIVE_SET_NEWTON));
  });
#endif
  // Along the default method's descent, with no stopping rule: the bending energy falls at every
  // iteration, while the distance and the normals to the clean surface are best early on.
  for(unsigned int cap : {25u, 50u, 100u, 200u, 500u})
    run_mode("default, " + std::to_string(cap) + " iterations", [&](Mesh& m) {
      return PMP::constrained_fairing(m, eps, CFP::energy_decrease_threshold(0.0).number_of_iterations(cap));
    });
  std::cout << "('!' after a deviation: that bound is violated)\n\n";

  table1_protocol(noisy, eps, reference.first, reference.second);
  const auto large = run_mode("", [&](Mesh& m) { return PMP::constrained_fairing(m, 8 * eps); }, false);
  table1_protocol(noisy, 8 * eps, large.first, large.second);
  return EXIT_SUCCESS;
}
