// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mean edge length h of a mesh: the unit in which tolerances relative to the mesh are given
// ("0.25h" on the command line) and in which the tests and benchmarks size their noise.

#ifndef CONSTRAINED_FAIRING_FRONT_END_MEAN_EDGE_LENGTH_H
#define CONSTRAINED_FAIRING_FRONT_END_MEAN_EDGE_LENGTH_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <cmath>

namespace Constrained_fairing_front_end {

// 0 for a mesh without edges.
template <typename PolygonMesh>
double mean_edge_length(const PolygonMesh& mesh)
{
  const auto vpm = get(CGAL::vertex_point, mesh);
  using Point = typename boost::property_traits<decltype(vpm)>::value_type;
  const auto squared_distance = typename CGAL::Kernel_traits<Point>::Kernel().compute_squared_distance_3_object();
  double sum = 0;
  for(auto e : edges(mesh))
    sum += std::sqrt(CGAL::to_double(squared_distance(get(vpm, source(e, mesh)), get(vpm, target(e, mesh)))));
  return num_edges(mesh) == 0 ? 0 : sum / double(num_edges(mesh));
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_MEAN_EDGE_LENGTH_H
