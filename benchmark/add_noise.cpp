// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Makes a noisy copy of a mesh for benchmarks and samples: every vertex moves uniformly at
// random inside a ball of radius R times the mean edge length.
//
//   add_noise IN R OUT [SEED]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

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
  double h = 0;
  for(auto e : edges(mesh))
    h += CGAL::Polygon_mesh_processing::edge_length(e, mesh);
  h /= double(num_edges(mesh));
  const double radius = std::stod(argv[2]) * h;

  std::mt19937 rng(argc > 4 ? static_cast<unsigned int>(std::stoul(argv[4])) : 1u);
  std::uniform_real_distribution<double> u(-1, 1);
  for(auto v : vertices(mesh))
  {
    K::Vector_3 d;
    do
      d = K::Vector_3(u(rng), u(rng), u(rng));
    while(d.squared_length() > 1);
    mesh.point(v) = mesh.point(v) + radius * d;
  }
  if(!CGAL::IO::write_polygon_mesh(argv[3], mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "error: cannot write " << argv[3] << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "mean edge length " << h << ", noise radius " << radius << std::endl;
  return EXIT_SUCCESS;
}
