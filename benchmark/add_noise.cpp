// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Makes a noisy copy of a mesh for benchmarks and samples: every vertex moves uniformly at
// random inside a ball of radius R times the mean edge length.
//
//   add_noise IN R OUT [SEED]

#include "benchmark_support.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <string>

using benchmark::Mesh;

int main(int argc, char* argv[])
{
  if(argc < 4)
  {
    std::cerr << "usage: add_noise IN R OUT [SEED]" << std::endl;
    return EXIT_FAILURE;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "error: cannot read " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }
  const double h = benchmark::mean_edge_length(mesh);
  const double radius = std::stod(argv[2]) * h;
  benchmark::add_noise(mesh, radius, argc > 4 ? static_cast<unsigned int>(std::stoul(argv[4])) : 1u);
  if(!CGAL::IO::write_polygon_mesh(argv[3], mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "error: cannot write " << argv[3] << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "mean edge length " << h << ", noise radius " << radius << std::endl;
  return EXIT_SUCCESS;
}
