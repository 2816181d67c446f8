// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fairs a mesh while keeping every vertex within epsilon of its input position.
//
//   constrained_fairing_example [IN] [EPS] [OUT]
//
// IN   a triangle mesh in any format CGAL reads (OFF, OBJ, PLY, STL); default: the bundled
//      noisy elephant
// EPS  the tolerance: absolute (0.002), or relative to the mean edge length h when it ends
//      with h (0.25h); default 0.25h
// OUT  where to write the faired mesh, full precision; default: faired.off

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(auto e : edges(mesh))
    sum += PMP::edge_length(e, mesh);
  return sum / double(num_edges(mesh));
}

// "0.002" is absolute, "0.25h" is 0.25 times the mean edge length. Returns false if malformed.
bool parse_epsilon(const std::string& text, const Mesh& mesh, double& epsilon)
{
  const bool relative = !text.empty() && text.back() == 'h';
  const std::string number = relative ? text.substr(0, text.size() - 1) : text;
  std::size_t used = 0;
  try
  {
    epsilon = std::stod(number, &used);
  }
  catch(const std::exception&)
  {
    return false;
  }
  if(used != number.size())
    return false;
  if(relative)
    epsilon *= mean_edge_length(mesh);
  return true;
}

int main(int argc, char* argv[])
{
  const std::string in = argc > 1 ? argv[1] : CGAL_CONSTRAINED_FAIRING_DATA_DIR "/elephant_noisy.off";
  const std::string eps_text = argc > 2 ? argv[2] : "0.25h";
  const std::string out = argc > 3 ? argv[3] : "faired.off";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }
  double epsilon = 0;
  if(!parse_epsilon(eps_text, mesh, epsilon))
  {
    std::cerr << "error: EPS must be a number, or a number followed by h (got " << eps_text << ")" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "input:       " << in << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces" << std::endl;
  std::cout << "epsilon:     " << epsilon << " (" << eps_text << ")" << std::endl;

  const auto start = std::chrono::steady_clock::now();
  const PMP::Constrained_fairing_result result = PMP::constrained_fairing(mesh, epsilon);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;

  if(!result)
  {
    std::cerr << "error: " << result.message << "; nothing written" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "iterations:  " << result.number_of_iterations << " ("
            << (result.status == PMP::Constrained_fairing_status::CONVERGED ? "converged" : "iteration limit")
            << ", " << result.number_of_cg_iterations << " conjugate gradient iterations)" << std::endl;
  std::cout << "energy:      " << result.initial_energy << " -> " << result.final_energy << std::endl;
  std::cout << "deviation:   " << result.max_deviation << " at most (bound " << epsilon << ")" << std::endl;
  std::cout << "time:        " << seconds.count() << " s" << std::endl;

  if(!CGAL::IO::write_polygon_mesh(out, mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "error: cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "output:      " << out << std::endl;
  return EXIT_SUCCESS;
}
