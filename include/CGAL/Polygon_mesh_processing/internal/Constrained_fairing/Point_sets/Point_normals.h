// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normals of a point set given without them, as CGAL estimates them: a jet fit over each
// point's k nearest neighbours (jet_estimate_normals), then oriented along a minimum spanning
// tree of the neighbours' graph (mst_orient_normals). The tree orients the component of the
// graph it starts in; the points it leaves go through it again, one component a time, so that
// every point's normal agrees with its neighbours'. Why the orientation matters: the points'
// tangent fans are oriented by them (Tangent_fans.h), and the normals along which the points
// move are sums over the fans' triangles.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NORMALS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NORMALS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The unit normals of the n > k points X, from their `k` nearest neighbours.
inline Points estimated_normals(const Points& X, std::size_t k)
{
  using Kernel = Exact_predicates_inexact_constructions_kernel;
  using Item = std::tuple<Kernel::Point_3, Kernel::Vector_3, std::size_t>;
  std::vector<Item> items;
  items.reserve(std::size_t(X.rows()));
  for(Eigen::Index i = 0; i < X.rows(); ++i)
    items.emplace_back(Kernel::Point_3(X(i, 0), X(i, 1), X(i, 2)), Kernel::Vector_3(0, 0, 0), std::size_t(i));
  const auto maps = parameters::point_map(Nth_of_tuple_property_map<0, Item>())
                      .normal_map(Nth_of_tuple_property_map<1, Item>());
  jet_estimate_normals<Parallel_if_available_tag>(items, unsigned(k), maps);
  Points N(X.rows(), 3);
  std::vector<Item> left = std::move(items);
  while(!left.empty())
  {
    const auto unoriented = mst_orient_normals(left, unsigned(k), maps);
    if(unoriented == left.begin()) // no progress: the rest keep the fit's sign
      break;
    for(auto it = left.begin(); it != unoriented; ++it)
    {
      const Kernel::Vector_3& n = std::get<1>(*it);
      N.row(Eigen::Index(std::get<2>(*it))) << n.x(), n.y(), n.z();
    }
    left.erase(left.begin(), unoriented);
    if(left.size() <= k) // too few for another tree
      break;
  }
  for(const Item& item : left)
  {
    const Kernel::Vector_3& n = std::get<1>(item);
    N.row(Eigen::Index(std::get<2>(item))) << n.x(), n.y(), n.z();
  }
  for(Eigen::Index i = 0; i < N.rows(); ++i)
  {
    const double length = point(N, i).norm();
    if(length > 0)
      point(N, i) /= length;
  }
  return N;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_NORMALS_H
