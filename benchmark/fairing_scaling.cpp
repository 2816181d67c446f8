// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the default call scales with the mesh size:
//
//   fairing_scaling [IN] [LEVELS] [--runs N]
//
// IN (default: the bundled elephant) is Loop subdivided 0, 1, ..., LEVELS times (default 3);
// each mesh gets noise of radius 0.25 h (h its mean edge length, seeded) and is faired with
// epsilon = 0.25 h. For each size: iterations, median time over N runs (default 3), time per
// iteration, peak resident memory so far, and, when CHOLMOD is available, the time with a
// CHOLMOD supernodal solver as a ratio to the default solver's, measured in the same process.

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <sys/resource.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using benchmark::Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

double peak_memory_mib()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024; // KiB on Linux
}

int main(int argc, char* argv[])
{
  const benchmark::Arguments arguments(argc, argv);
  const std::vector<std::string>& args = arguments.positional;
  const int runs = arguments.runs;
  const std::string in = args.size() > 0 ? args[0] : CONSTRAINED_FAIRING_DATA_DIR "/elephant.off";
  const unsigned int levels = args.size() > 1 ? static_cast<unsigned int>(std::stoul(args[1])) : 3u;

  Mesh base;
  if(!CGAL::IO::read_polygon_mesh(in, base))
  {
    std::cerr << "error: cannot read " << in << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << in << ", Loop subdivided 0.." << levels << " times, noise and epsilon 0.25 h, median of " << runs
            << " runs\n\n"
            << std::setw(10) << "vertices" << std::setw(6) << "it" << std::setw(10) << "s" << std::setw(12) << "ms/it"
            << std::setw(12) << "peak MiB" << std::setw(10) << "energy"
#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
            << std::setw(16) << "CHOLMOD/default"
#endif
            << "\n";

  for(unsigned int level = 0; level <= levels; ++level)
  {
    Mesh clean = base;
    CGAL::Subdivision_method_3::Loop_subdivision(clean, CGAL::parameters::number_of_iterations(level));
    const double eps = 0.25 * benchmark::mean_edge_length(clean);
    Mesh noisy = clean;
    benchmark::add_noise(noisy, eps, 1);

    PMP::Constrained_fairing_result r;
    const double seconds = benchmark::median_seconds(runs, [&] {
      Mesh m = noisy;
      r = PMP::constrained_fairing(m, eps);
    });
    std::cout << std::setw(10) << num_vertices(noisy) << std::setw(6) << r.number_of_iterations << std::setw(10)
              << std::setprecision(3) << seconds << std::setw(12) << 1000 * seconds / double(r.number_of_iterations)
              << std::setw(12) << std::setprecision(4) << peak_memory_mib() << std::setw(10) << r.final_energy;
#ifdef CGAL_CONSTRAINED_FAIRING_HAS_CHOLMOD
    using Cholmod =
      CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;
    const double cholmod_seconds = benchmark::median_seconds(runs, [&] {
      Mesh m = noisy;
      PMP::constrained_fairing(m, eps, CGAL::parameters::sparse_linear_solver(Cholmod()));
    });
    std::cout << std::setw(16) << std::setprecision(3) << cholmod_seconds / seconds;
#endif
    std::cout << std::endl;
  }
  return EXIT_SUCCESS;
}
