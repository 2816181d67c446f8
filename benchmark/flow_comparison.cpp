// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Constrained fairing against CGAL's mean curvature flow (smooth_shape) at equal energy: the
// flow runs step by step (time 0.03 h^2 each) until its bending energy is down to the
// fairing's, or stops decreasing (the flow then pinches thin parts, and the energy rises
// again), and both results are compared with the input: the largest move, and the volume
// change (for closed meshes). Writes both results for the manual's figure, the flow at its
// lowest energy.
//
//   flow_comparison NOISY EPS FAIRED_OUT FLOW_OUT

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

using benchmark::Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

double bending_energy(const Mesh& mesh)
{
  Mesh copy = mesh;
  return PMP::constrained_fairing(copy, 1, CGAL::parameters::number_of_iterations(0)).final_bending_energy;
}

double largest_move(const Mesh& result, const Mesh& input)
{
  double largest = 0;
  for(auto v : vertices(input))
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(result.point(v), input.point(v))));
  return largest;
}

int main(int argc, char* argv[])
{
  std::cout << benchmark::machine_description() << std::endl; // the CPU and threads of every figure below
  if(argc < 5)
  {
    std::cerr << "usage: flow_comparison NOISY EPS FAIRED_OUT FLOW_OUT" << std::endl;
    return EXIT_FAILURE;
  }
  Mesh input;
  if(!CGAL::IO::read_polygon_mesh(argv[1], input))
  {
    std::cerr << "error: cannot read " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }
  const double eps = std::stod(argv[2]), h = benchmark::mean_edge_length(input);
  const bool closed = CGAL::is_closed(input);

  Mesh faired = input;
  const auto result = PMP::constrained_fairing(faired, eps);
  Mesh flow = input, lowest = input;
  double energy = bending_energy(flow), lowest_energy = energy;
  std::size_t steps = 0, lowest_steps = 0;
  while(steps < 500 && energy > result.final_energy && energy <= 1.5 * lowest_energy)
  {
    PMP::smooth_shape(flow, 0.03 * h * h, CGAL::parameters::number_of_iterations(1));
    energy = bending_energy(flow);
    ++steps;
    if(energy < lowest_energy)
    {
      lowest = flow;
      lowest_energy = energy;
      lowest_steps = steps;
    }
  }
  flow = lowest;
  energy = lowest_energy;
  steps = lowest_steps;
  std::cout << "constrained fairing: energy " << result.final_energy << ", largest move " << largest_move(faired, input)
            << " (eps " << eps << ")";
  if(closed)
    std::cout << ", volume change " << 100 * (PMP::volume(faired) / PMP::volume(input) - 1) << " %";
  std::cout << "\nsmooth_shape at its lowest energy, after " << steps << " steps: energy " << energy << ", largest move "
            << largest_move(flow, input);
  if(closed)
    std::cout << ", volume change " << 100 * (PMP::volume(flow) / PMP::volume(input) - 1) << " %";
  std::cout << std::endl;
  const auto precision = CGAL::parameters::stream_precision(17);
  return CGAL::IO::write_polygon_mesh(argv[3], faired, precision) && CGAL::IO::write_polygon_mesh(argv[4], flow, precision)
           ? EXIT_SUCCESS
           : EXIT_FAILURE;
}
