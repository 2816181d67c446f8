// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A scan faired before it is meshed: the points of a .pwn file (points with their normals), the
// noise estimated from the points themselves as epsilon, every point faired within it, in its
// order, and the normals at the result written back. Writes faired.pwn, and fails unless every
// point kept its place in the file and stayed within epsilon of its input position.
//
//   point_set_fairing_example [IN.pwn]

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_points.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level_of_points.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_with_normal = std::pair<K::Point_3, K::Vector_3>;
using Point_map = CGAL::First_of_pair_property_map<Point_with_normal>;
using Normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const std::string in = argc > 1 ? argv[1] : CGAL_CONSTRAINED_FAIRING_DATA_DIR "/oni.pwn";
  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(in, std::back_inserter(points),
                            CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())))
  {
    std::cerr << "error: cannot read points with normals from " << in << std::endl;
    return EXIT_FAILURE;
  }
  const std::vector<Point_with_normal> input = points;

  const double epsilon = PMP::estimate_noise_level_of_points(points, CGAL::parameters::point_map(Point_map()));
  std::cout << points.size() << " points, estimated noise level: " << epsilon << std::endl;

  // The normal map is writable, so the normals at the result replace the scanner's.
  const PMP::Constrained_fairing_result result = PMP::constrained_fairing_of_points(
    points, epsilon, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  if(!result)
  {
    std::cerr << "error: " << result.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "bending energy " << result.initial_bending_energy << " -> " << result.final_bending_energy << ", "
            << result.number_of_isolated_points << " isolated points left in place, largest move "
            << result.max_deviation << std::endl;

  // The bound in double, point by point: the i-th point of the result is the i-th of the input.
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!(CGAL::squared_distance(points[i].first, input[i].first) <= epsilon * epsilon))
    {
      std::cerr << "error: point " << i << " moved farther than epsilon" << std::endl;
      return EXIT_FAILURE;
    }
  if(!(result.final_bending_energy < result.initial_bending_energy))
  {
    std::cerr << "error: the bending energy did not go down" << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_points("faired.pwn", points,
                                CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).stream_precision(17))
           ? EXIT_SUCCESS
           : EXIT_FAILURE;
}
