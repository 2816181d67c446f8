// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fairs a noisy sphere through the installed package, and checks the bound, the energy and
// the noise estimate before and after.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main()
{
  Mesh mesh;
  CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(3));
  // A deterministic bump on every vertex: a noisy sphere.
  const double eps = 0.01;
  for(auto v : vertices(mesh))
    mesh.point(v) = mesh.point(v) + (eps * std::sin(double(v.idx()) * 12.9898)) * K::Vector_3(0.6, 0.48, 0.64);
  const Mesh noisy = mesh;
  std::vector<K::Point_3> input;
  for(auto v : vertices(mesh))
    input.push_back(mesh.point(v));

  const PMP::Constrained_fairing_result result = PMP::constrained_fairing(mesh, eps);
  bool within = true;
  for(auto v : vertices(mesh))
    within = within && CGAL::squared_distance(mesh.point(v), input[v.idx()]) <= eps * eps;
  const bool passed = result && within && result.final_energy < result.initial_energy &&
                      PMP::estimate_noise_level(mesh) < PMP::estimate_noise_level(noisy);
  std::cout << "consumer: energy " << result.initial_energy << " -> " << result.final_energy << ", "
            << (passed ? "passed" : "FAILED") << std::endl;
  return passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
