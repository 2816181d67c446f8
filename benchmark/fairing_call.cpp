// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default call on one mesh file as a C++ program makes it: the baseline against which
// benchmark/python_batch.py measures the Python module on the same arrays.
//
//   fairing_call --write-case OUT [MESH] [--level L] [--clean CLEAN]
//       writes fairing_scaling's case: MESH (default: the bundled bunny) Loop subdivided L
//       times (default 1: 301,632 triangles), with seeded noise of 0.25 h; CLEAN gets the
//       subdivided mesh before the noise
//   fairing_call IN [--runs N] [--output OUT]
//       reads IN as the tool does, fairs it within 0.25 h (h its mean edge length), and prints
//       on one line the median times of N runs (default 1) of the call on the mesh and of the
//       mesh's construction from the file's arrays followed by the call,
//       "seconds S from_arrays A iterations I"; OUT gets the result, at full precision

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using benchmark::Mesh;
using benchmark::Point;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const benchmark::Arguments arguments(argc, argv);
  const std::string case_file = arguments.option("write-case", "");
  if(!case_file.empty())
  {
    Mesh base, noisy;
    std::string name;
    if(!benchmark::read_base_mesh(arguments, base, name))
      return EXIT_FAILURE;
    const auto level = static_cast<unsigned int>(std::stoul(arguments.option("level", "1")));
    benchmark::make_noisy_case(base, level, noisy);
    const std::string clean_file = arguments.option("clean", "");
    if(!clean_file.empty())
    {
      CGAL::Subdivision_method_3::Loop_subdivision(base, CGAL::parameters::number_of_iterations(level));
      if(!CGAL::IO::write_polygon_mesh(clean_file, base, CGAL::parameters::stream_precision(17)))
        return EXIT_FAILURE;
    }
    return CGAL::IO::write_polygon_mesh(case_file, noisy, CGAL::parameters::stream_precision(17)) ? EXIT_SUCCESS
                                                                                                  : EXIT_FAILURE;
  }

  // The file read once as a soup, the arrays a program holds, and as the mesh made of them.
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  Mesh mesh;
  if(arguments.positional.empty() || !CGAL::IO::read_polygon_soup(arguments.positional[0], points, triangles))
  {
    std::cerr << "usage: fairing_call IN [--runs N] [--output OUT] | fairing_call --write-case OUT [MESH] [--level L] "
                 "[--clean CLEAN]"
              << std::endl;
    return EXIT_FAILURE;
  }
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  const double eps = 0.25 * benchmark::mean_edge_length(mesh);
  PMP::Constrained_fairing_result result;
  // Each run times the call on the mesh, then the mesh made of the arrays and the call on it.
  std::vector<double> on_mesh, from_arrays;
  for(int run = 0; run < (arguments.runs < 1 ? 1 : arguments.runs); ++run)
  {
    for(auto v : vertices(mesh))
      mesh.point(v) = points[v.idx()];
    auto start = std::chrono::steady_clock::now();
    result = PMP::constrained_fairing(mesh, eps);
    on_mesh.push_back(benchmark::seconds_since(start));
    start = std::chrono::steady_clock::now();
    Mesh made;
    PMP::polygon_soup_to_polygon_mesh(points, triangles, made);
    PMP::constrained_fairing(made, eps);
    from_arrays.push_back(benchmark::seconds_since(start));
  }
  if(!result)
  {
    std::cerr << "error: " << result.message << std::endl;
    return EXIT_FAILURE;
  }
  const auto median = [](std::vector<double> t) {
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  };
  std::cout << "seconds " << median(on_mesh) << " from_arrays " << median(from_arrays) << " iterations "
            << result.number_of_iterations << std::endl;
  const std::string output = arguments.option("output", "");
  if(!output.empty() && !CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}
