// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fairs a noisy mesh: its bending energy is minimized while every vertex stays within epsilon
// of its input position. Writes faired.off, and fails unless the bound holds and the bending
// energy went down.
//
//   constrained_fairing_example [IN] [EPS]
//
// EPS defaults to a quarter of the mean edge length. The tool `constrained_fairing` does the
// same on any file, with every option.

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const std::string in = argc > 1 ? argv[1] : CGAL_CONSTRAINED_FAIRING_DATA_DIR "/elephant_noisy.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: cannot read a triangle mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }
  double epsilon = argc > 2 ? std::stod(argv[2]) : 0;
  if(epsilon == 0)
  {
    double sum = 0;
    for(auto e : edges(mesh))
      sum += PMP::edge_length(e, mesh);
    epsilon = 0.25 * sum / double(num_edges(mesh));
  }

  const PMP::Constrained_fairing_result result = PMP::constrained_fairing(mesh, epsilon);
  if(!result)
  {
    std::cerr << "error: " << result.message << std::endl;
    return EXIT_FAILURE;
  }
  // The bending energy is the paper's; the objective minimized adds a barrier against slivers.
  std::cout << in << ": " << result.number_of_iterations << " iterations, bending energy "
            << result.initial_bending_energy << " -> " << result.final_bending_energy;
  if(result.initial_energy != result.initial_bending_energy || result.final_energy != result.final_bending_energy)
    std::cout << ", objective " << result.initial_energy << " -> " << result.final_energy;
  std::cout << ", every vertex within " << result.max_deviation << " of its input position" << std::endl;
  if(!(result.max_deviation <= epsilon && result.final_bending_energy < result.initial_bending_energy))
  {
    std::cerr << "error: the bound " << epsilon << " or the decrease of the bending energy does not hold" << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("faired.off", mesh, CGAL::parameters::stream_precision(17)) ? EXIT_SUCCESS
                                                                                                   : EXIT_FAILURE;
}
