// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fairing part of a mesh: the faces above the middle height, with a per-vertex tolerance
// (smaller towards the top) and the deviation of each vertex as output. Everything outside the
// region, and its border, stays bit-identical. Fails unless each vertex kept its own tolerance
// and the bending energy went down.
//
//   region_fairing_example [IN]

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
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
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const double middle = (box.zmin() + box.zmax()) / 2, epsilon = 0.01 * (box.zmax() - box.zmin());

  std::vector<Mesh::Face_index> region;
  for(auto f : faces(mesh))
    if(mesh.point(target(halfedge(f, mesh), mesh)).z() > middle)
      region.push_back(f);
  auto tolerance = mesh.add_property_map<vertex_descriptor, double>("v:tolerance").first;
  auto deviation = mesh.add_property_map<vertex_descriptor, double>("v:deviation").first;
  for(auto v : vertices(mesh))
    tolerance[v] = epsilon * (box.zmax() - mesh.point(v).z()) / (box.zmax() - middle);

  const PMP::Constrained_fairing_result result = PMP::constrained_fairing(
    region, mesh, epsilon, CFP::vertex_tolerance_map(tolerance, CFP::vertex_deviation_map(deviation)));
  if(!result)
  {
    std::cerr << "error: " << result.message << std::endl;
    return EXIT_FAILURE;
  }
  double largest = 0;
  for(auto v : vertices(mesh))
    largest = (std::max)(largest, deviation[v] / (tolerance[v] > 0 ? tolerance[v] : 1));
  std::cout << region.size() << " faces faired, " << result.number_of_fixed_vertices << " vertices kept; "
            << "largest move " << largest << " of the vertex's own tolerance; bending energy "
            << result.initial_bending_energy << " -> " << result.final_bending_energy;
  // The objective minimized adds a barrier against slivers.
  if(result.initial_energy != result.initial_bending_energy || result.final_energy != result.final_bending_energy)
    std::cout << ", objective " << result.initial_energy << " -> " << result.final_energy;
  std::cout << std::endl;
  if(!(largest <= 1 && result.final_bending_energy < result.initial_bending_energy))
  {
    std::cerr << "error: a tolerance or the decrease of the bending energy does not hold" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
