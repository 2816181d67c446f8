// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The order in which the solver stores the vertices: along a Hilbert curve through their input
// positions (CGAL::hilbert_sort). Every evaluation of the energy visits each triangle and
// hinge with its vertices, tile by tile, a tile being a run of consecutive vertices
// (Bending_energy.h): in this order a tile is a compact patch of the surface, whose data fits
// in a cache, while in the order of a file neighbours are often far apart in memory. The order
// depends only on the positions and their order in `vertices(tmesh)`, so results stay
// bit-identical run to run and across mesh data structures.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HILBERT_ORDER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HILBERT_ORDER_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The position of each vertex of X (finite coordinates) in the Hilbert order.
inline std::vector<Index> hilbert_rank(const Points& X)
{
  using Kernel = CGAL::Simple_cartesian<double>;
  using Point = Kernel::Point_3;
  const std::size_t n = static_cast<std::size_t>(X.rows());
  std::vector<Point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(X(i, 0), X(i, 1), X(i, 2));
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i)
    order[i] = i;
  using Point_map = typename CGAL::Pointer_property_map<Point>::type;
  CGAL::hilbert_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, Point_map>(CGAL::make_property_map(points)));
  std::vector<Index> rank(n);
  for(std::size_t k = 0; k < n; ++k)
    rank[order[k]] = static_cast<Index>(k);
  return rank;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HILBERT_ORDER_H
