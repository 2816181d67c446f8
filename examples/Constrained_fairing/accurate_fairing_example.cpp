// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A noisy scan of unknown accuracy: the noise level estimated from the mesh itself as epsilon,
// and the accurate objective, which ends closer to the true surface than the fairest one.
// Writes accurate.off, and fails unless the bound holds and both the objective and the bending
// energy went down.
//
//   accurate_fairing_example [IN]

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;

int main(int argc, char* argv[])
{
  const std::string in = argc > 1 ? argv[1] : CGAL_CONSTRAINED_FAIRING_DATA_DIR "/elephant_noisy.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: cannot read a triangle mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }

  const double epsilon = PMP::estimate_noise_level(mesh);
  std::cout << "estimated noise level: " << epsilon << std::endl;

  const PMP::Constrained_fairing_result result = PMP::constrained_fairing(
    mesh, epsilon, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE));
  if(!result)
  {
    std::cerr << "error: " << result.message << std::endl;
    return EXIT_FAILURE;
  }
  // The objective adds to the bending energy a fidelity term and a barrier against slivers.
  std::cout << "bending energy " << result.initial_bending_energy << " -> " << result.final_bending_energy
            << ", objective " << result.initial_energy << " -> " << result.final_energy << ", "
            << result.number_of_unfolded_faces << " folded faces repaired, largest move " << result.max_deviation
            << std::endl;
  if(!(result.max_deviation <= epsilon && result.final_energy <= result.initial_energy &&
       result.final_bending_energy < result.initial_bending_energy))
  {
    std::cerr << "error: the bound or the decrease of the energies does not hold" << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("accurate.off", mesh, CGAL::parameters::stream_precision(17)) ? EXIT_SUCCESS
                                                                                                     : EXIT_FAILURE;
}
