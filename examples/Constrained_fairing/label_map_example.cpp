// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The surfaces of a label map, one closed surface per label with their interfaces shared: two
// labels that fill a ball on either side of a tilted plane, inside a third, on slices 2 voxels
// thick. Multi-label surface nets, all interfaces faired at once within the voxels, then each
// label's surface, written as label_L.off. Fails unless every point stayed in its box and
// every label's surface is closed, outward and fairer than before.
//
//   label_map_example

#include <CGAL/Polygon_mesh_processing/constrained_fairing_of_interfaces.h>
#include <CGAL/Polygon_mesh_processing/label_surface.h>
#include <CGAL/Polygon_mesh_processing/label_surface_nets.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;

int main()
{
  // labels[(i * 40 + j) * 20 + k]: voxel (i, j, k), centred at (i, j, 2 k).
  const std::array<std::size_t, 3> size{40, 40, 20};
  const std::array<double, 3> spacing{1, 1, 2}, origin{0, 0, 0};
  std::vector<std::uint8_t> labels(size[0] * size[1] * size[2], 0);
  for(std::size_t i = 0; i < size[0]; ++i)
    for(std::size_t j = 0; j < size[1]; ++j)
      for(std::size_t k = 0; k < size[2]; ++k)
      {
        const double x = double(i) - 19.5, y = double(j) - 19.5, z = 2 * double(k) - 19.5;
        const double r = std::sqrt(x * x + y * y + z * z);
        labels[(i * size[1] + j) * size[2] + k] = r < 12 ? (x < 0.3 * z ? 1 : 2) : r < 17 ? 3 : 0;
      }

  std::vector<K::Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<std::uint8_t, 2> > face_labels;
  std::vector<std::array<double, 3> > half_extents;
  PMP::label_surface_nets(labels.data(), size, spacing, origin, points, triangles, face_labels, half_extents);
  const std::vector<K::Point_3> nets = points;

  // Each point in its box: its dual cell, kept apart from the other points' boxes.
  const PMP::Constrained_fairing_result r = PMP::constrained_fairing_of_interfaces(
    points, triangles, face_labels, 2.0, CFP::vertex_box_half_extents_map(CGAL::make_property_map(half_extents)));
  if(!r)
  {
    std::cerr << "fairing failed: " << r.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points, " << triangles.size() << " triangles: bending energy "
            << r.initial_bending_energy << " -> " << r.final_bending_energy << " in " << r.number_of_iterations
            << " iterations, " << r.number_of_fixed_vertices
            << " points fixed where junction lines end or branch or four labels meet" << std::endl;
  bool ok = r.final_bending_energy < r.initial_bending_energy;
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < 3; ++c)
      ok = ok && std::abs(points[v][c] - nets[v][c]) <= half_extents[v][std::size_t(c)];

  for(std::uint8_t label : {1, 2, 3})
  {
    Mesh surface;
    PMP::label_surface(points, triangles, face_labels, label, surface);
    const bool closed = CGAL::is_closed(surface) && PMP::volume(surface) > 0;
    const std::string file = "label_" + std::to_string(label) + ".off";
    std::cout << "label " << int(label) << ": " << surface.number_of_faces() << " triangles, volume "
              << PMP::volume(surface) << (closed ? ", closed and outward, " : ", NOT CLOSED, ") << "written to "
              << file << std::endl;
    ok = ok && closed && CGAL::IO::write_polygon_mesh(file, surface, CGAL::parameters::stream_precision(17));
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
