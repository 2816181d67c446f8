// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fairs the terraced surface extracted from a segmented volume, each vertex kept inside its
// voxel: the bundled elephant voxelized on slices 3 times thicker than the pixels (as in CT),
// its surface nets (surface_nets.h), then constrained fairing with the voxel as each vertex's
// box. Writes the staircase and the result, and reports how far each is from the elephant;
// fails unless every vertex stayed in its voxel and the result is both closer to the elephant
// and fairer than the staircase.
//
//   voxel_fairing_example [STAIRCASE_OUT] [FAIRED_OUT]

#include "surface_nets.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/version_macros.h>
#if CGAL_VERSION_MAJOR >= 6
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif

#include <cmath>
#include <cstdlib>
#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;
#if CGAL_VERSION_MAJOR >= 6
using Tree = CGAL::AABB_tree<CGAL::AABB_traits_3<K, CGAL::AABB_face_graph_triangle_primitive<Mesh> > >;
#else
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh> > >;
#endif

// RMS distance of the vertices of m to the shape, in pixels.
double rms_distance(const Mesh& m, const Tree& shape, double pixel)
{
  double sum = 0;
  for(auto v : vertices(m))
    sum += shape.squared_distance(m.point(v));
  return std::sqrt(sum / double(num_vertices(m))) / pixel;
}

int main(int argc, char* argv[])
{
  Mesh elephant;
  if(!CGAL::IO::read_polygon_mesh(CGAL_CONSTRAINED_FAIRING_DATA_DIR "/elephant.off", elephant))
    return EXIT_FAILURE;
  const Tree tree(faces(elephant).first, faces(elephant).second, elephant);
  const CGAL::Side_of_triangle_mesh<Mesh, K> inside(tree);

  // 64 pixels along the longest side, slices 3 pixels thick, one empty layer around.
  const CGAL::Bbox_3 box = PMP::bbox(elephant);
  const double pixel = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}) / 64;
  const std::array<double, 3> spacing{pixel, pixel, 3 * pixel};
  std::array<std::size_t, 3> size;
  std::array<double, 3> origin;
  for(int a = 0; a < 3; ++a)
  {
    origin[a] = box.min(a) - 1.5 * spacing[a];
    size[a] = std::size_t(std::ceil((box.max(a) - box.min(a)) / spacing[a])) + 4;
  }
  const voxels::Grid grid(size, spacing, origin, [&](double x, double y, double z) {
    return inside(K::Point_3(x, y, z)) == CGAL::ON_BOUNDED_SIDE;
  });
  Mesh staircase;
  if(!voxels::surface_nets(grid, staircase))
    return EXIT_FAILURE;

  // Each vertex sits at its voxel's centre: the voxel is the box of half its size around it.
  Mesh faired = staircase;
  const std::array<double, 3> half_voxel{spacing[0] / 2, spacing[1] / 2, spacing[2] / 2};
  const auto result = PMP::constrained_fairing(faired, half_voxel[2], CFP::box_half_extents(half_voxel));
  if(!result)
  {
    std::cerr << "error: " << result.message << std::endl;
    return EXIT_FAILURE;
  }
  const double rms_staircase = rms_distance(staircase, tree, pixel), rms_faired = rms_distance(faired, tree, pixel);
  std::cout << num_vertices(staircase) << " vertices; distance to the elephant (RMS, pixels) / bending energy:\n"
            << "  surface nets:        " << rms_staircase << " / " << result.initial_bending_energy << "\n"
            << "  constrained fairing: " << rms_faired << " / " << result.final_bending_energy << std::endl;
  if(result.initial_energy != result.initial_bending_energy || result.final_energy != result.final_bending_energy)
    std::cout << "objective (with the barrier against slivers) " << result.initial_energy << " -> "
              << result.final_energy << std::endl;
  // The vertices keep their order: each one's voxel is the box around its staircase position.
  bool in_voxel = true;
  for(auto v : vertices(faired))
    for(int a = 0; a < 3; ++a)
      in_voxel = in_voxel && std::abs(faired.point(v)[a] - staircase.point(v)[a]) <= half_voxel[a];
  if(!(in_voxel && rms_faired < rms_staircase && result.final_bending_energy < result.initial_bending_energy))
  {
    std::cerr << "error: a vertex left its voxel, or the result is not closer to the elephant and fairer" << std::endl;
    return EXIT_FAILURE;
  }
  const bool written =
    CGAL::IO::write_polygon_mesh(argc > 1 ? argv[1] : "staircase.off", staircase, CGAL::parameters::stream_precision(17)) &&
    CGAL::IO::write_polygon_mesh(argc > 2 ? argv[2] : "faired_voxels.off", faired, CGAL::parameters::stream_precision(17));
  return written ? EXIT_SUCCESS : EXIT_FAILURE;
}
