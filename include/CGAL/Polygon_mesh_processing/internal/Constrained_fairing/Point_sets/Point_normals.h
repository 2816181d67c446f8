// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normals of a point set given without them, as CGAL estimates them, on the neighbours the
// point set already has (Point_neighbours.h): each a jet fit of degree 2 over the point and its
// k nearest (CGAL's Monge_via_jet_fitting, as jet_estimate_normals() fits), then oriented
// along a minimum spanning tree of the neighbours' graph, as mst_orient_normals() orients (Hoppe
// et al. 1992: an edge's weight 1 - |n_i . n_j|, the tree grown from the highest point, whose
// normal points up), one component after another, so that every point's normal agrees with its
// neighbours'. Why not CGAL's two functions: they search the neighbours again and hold the
// neighbours' graph as a Boost graph, about 3,200 bytes per point at k = 32 (10 times what the
// fairing holds); the tree here, grown by Prim's method, holds a heap and two arrays. Why the
// orientation matters: the points' tangent fans are oriented by the normals (Tangent_fans.h),
// and the normals along which the points move are sums over the fans' triangles.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NORMALS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NORMALS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_neighbours.h>

#include <CGAL/Eigen_svd.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Each point's unoriented unit normal: the jet fit over the point and its k nearest (a plane
// where they are fewer than the quadric's 6).
inline Points jet_normals(const Points& X, const Point_neighbours& neighbours)
{
  using Kernel = Exact_predicates_inexact_constructions_kernel;
  using Fit = Monge_via_jet_fitting<Kernel, Simple_cartesian<double>, Eigen_svd>;
  const auto at = [&X](Index i) { return Kernel::Point_3(X(i, 0), X(i, 1), X(i, 2)); };
  Points N(X.rows(), 3);
  parallel_for_blocks(neighbours.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
    std::vector<Kernel::Point_3> local;
    for(std::size_t i = begin; i < end; ++i)
    {
      local.assign(1, at(Index(i)));
      for(const Index* j = neighbours.begin(i); j != neighbours.end(i); ++j)
        local.push_back(at(*j));
      const unsigned degree = local.size() >= 6 ? 2 : 1; // a quadric needs 6 points, a plane 3
      const Kernel::Vector_3 n = Fit()(local.begin(), local.end(), degree, 1).normal_direction();
      point(N, Eigen::Index(i)) = Eigen::Vector3d(n.x(), n.y(), n.z()).normalized();
    }
  });
  return N;
}

// Turns the normals N so that each agrees with its parent's in a minimum spanning tree of the
// neighbours' graph, the tree of each component grown from its highest point, pointed up.
inline void orient_along_spanning_tree(const Points& X, const Point_neighbours& neighbours, Points& N)
{
  const std::size_t n = neighbours.size();
  std::vector<bool> reached(n, false);
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  using Edge = std::tuple<double, Index, Index>; // weight, the point it reaches, from; ties by index
  std::priority_queue<Edge, std::vector<Edge>, std::greater<Edge> > heap;
  const auto reach = [&](Index i) {
    reached[std::size_t(i)] = true;
    for(const Index* j = neighbours.begin(std::size_t(i)); j != neighbours.end(std::size_t(i)); ++j)
    {
      const double weight = 1 - std::abs(point(N, i).dot(point(N, *j)));
      if(!reached[std::size_t(*j)] && weight < best[std::size_t(*j)])
      {
        best[std::size_t(*j)] = weight;
        heap.emplace(weight, *j, i);
      }
    }
  };
  // the highest point first, then the highest of those no tree has reached
  std::vector<Index> by_height(n);
  for(std::size_t i = 0; i < n; ++i)
    by_height[i] = Index(i);
  std::sort(by_height.begin(), by_height.end(),
            [&X](Index a, Index b) { return X(a, 2) > X(b, 2) || (X(a, 2) == X(b, 2) && a < b); });
  for(const Index source : by_height)
  {
    if(reached[std::size_t(source)])
      continue;
    if(N(source, 2) < 0)
      point(N, source) = -point(N, source);
    reach(source);
    while(!heap.empty())
    {
      const auto [weight, i, from] = heap.top();
      heap.pop();
      if(reached[std::size_t(i)])
        continue;
      if(point(N, i).dot(point(N, from)) < 0)
        point(N, i) = -point(N, i);
      reach(i);
    }
  }
}

// The unit normals of the points X, from their neighbours, oriented.
inline Points estimated_normals(const Points& X, const Point_neighbours& neighbours)
{
  Points N = jet_normals(X, neighbours);
  orient_along_spanning_tree(X, neighbours, N);
  return N;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NORMALS_H
