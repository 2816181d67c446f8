// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mean edge length h of a mesh: the unit in which tolerances relative to the mesh are given
// ("0.25h" on the command line) and in which the tests and benchmarks size their noise.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MEAN_EDGE_LENGTH_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MEAN_EDGE_LENGTH_H

#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <cmath>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// 0 for a mesh without edges.
template <typename PolygonMesh>
double mean_edge_length(const PolygonMesh& mesh)
{
  const auto vpm = get(CGAL::vertex_point, mesh);
  double sum = 0;
  for(auto e : edges(mesh))
    sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(e, mesh)), get(vpm, target(e, mesh)))));
  return num_edges(mesh) == 0 ? 0 : sum / double(num_edges(mesh));
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MEAN_EDGE_LENGTH_H
