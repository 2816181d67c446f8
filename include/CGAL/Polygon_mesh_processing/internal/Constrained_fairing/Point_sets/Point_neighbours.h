// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The k nearest neighbours of each point of a point set, by CGAL's kd-tree (Spatial_searching),
// nearest first and ties by index, so that they depend on the points only; with the distance to
// the k-th, the size of the point's neighbourhood. The queries run in parallel on the built
// tree, one point's at a time (Parallel_for.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NEIGHBOURS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NEIGHBOURS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/assertions.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Point_neighbours
{
public:
  // The `k` nearest of each of the n points X (k < n), itself left out.
  Point_neighbours(const Points& X, std::size_t k) : m_k(k)
  {
    using Kernel = Exact_predicates_inexact_constructions_kernel;
    using Point_map = Pointer_property_map<Kernel::Point_3>::const_type;
    using Traits = Search_traits_adapter<std::size_t, Point_map, Search_traits_3<Kernel> >;
    using Search = Orthogonal_k_neighbor_search<Traits>;
    const std::size_t n = static_cast<std::size_t>(X.rows());
    CGAL_precondition(k < n);
    std::vector<Kernel::Point_3> points(n);
    for(std::size_t i = 0; i < n; ++i)
      points[i] = Kernel::Point_3(X(Eigen::Index(i), 0), X(Eigen::Index(i), 1), X(Eigen::Index(i), 2));
    std::vector<std::size_t> indices(n);
    for(std::size_t i = 0; i < n; ++i)
      indices[i] = i;
    const Point_map map(points.data());
    typename Search::Tree tree(indices.begin(), indices.end(), typename Search::Splitter(), Traits(map));
    tree.build();
    m_neighbours.resize(n * k);
    m_radius.resize(n);
    parallel_for_blocks(n, [&](std::size_t begin, std::size_t end, std::size_t) {
      std::vector<std::pair<double, std::size_t> > found;
      for(std::size_t i = begin; i < end; ++i)
      {
        // k + 1, and any point at the same distance as the last: ties broken by index
        Search search(tree, points[i], unsigned(k + 1), 0, true, typename Search::Distance(map));
        found.clear();
        for(const auto& [j, squared] : search)
          if(j != i)
            found.emplace_back(squared, j);
        std::sort(found.begin(), found.end());
        found.resize((std::min)(found.size(), k));
        for(std::size_t r = 0; r < found.size(); ++r)
          m_neighbours[i * k + r] = Index(found[r].second);
        m_radius[i] = found.empty() ? 0 : std::sqrt(found.back().first);
      }
    });
  }

  std::size_t k() const { return m_k; }
  std::size_t size() const { return m_radius.size(); }
  // Point i's neighbours, nearest first.
  const Index* begin(std::size_t i) const { return m_neighbours.data() + i * m_k; }
  const Index* end(std::size_t i) const { return begin(i) + m_k; }
  // The distance from point i to its k-th neighbour.
  double radius(std::size_t i) const { return m_radius[i]; }

private:
  std::size_t m_k;
  std::vector<Index> m_neighbours;
  std::vector<double> m_radius;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NEIGHBOURS_H
