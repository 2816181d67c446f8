// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a point set must be, and what it is made of once accepted: each point's neighbours,
// normal and tangent fan. The defects, each named with the first point it concerns, in the
// order they are looked for: too few neighbours asked, a NaN or infinite coordinate, a given
// normal zero, NaN or infinite, no more points than neighbours, two points that coincide (their
// fans would have no triangle between them), no point with neighbours around it (all on one
// line). A point with no usable neighbourhood is isolated: it stays where it is, outside
// every other's fan, and is counted, never dropped. It is one farther from its k-th neighbour
// than `isolated_radius_factor` times the median of that distance over all points (an outlier
// of a scan, four times as far as a typical point is from its k-th neighbour: a sixteenth of
// the typical density), or one whose neighbours leave no triangle around it.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_neighbours.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_normals.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Tangent_fans.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

constexpr double isolated_radius_factor = 4;

struct Point_set_structure
{
  Input_error error;             // the first defect, if any; then nothing else is set
  Points normals;                // unit, the user's or estimated
  std::vector<bool> isolated;
  std::vector<Tangent_fan> fans; // none for an isolated point
};

namespace point_set_check {

// The first point of a NaN or infinite coordinate, of a bad given normal; the normals made unit.
inline Input_error value_error(const Points& X, std::optional<Points>& normals)
{
  for(Eigen::Index i = 0; i < X.rows(); ++i)
    if(!X.row(i).allFinite())
      return non_finite_coordinate_error(std::size_t(i));
  if(normals)
    for(Eigen::Index i = 0; i < X.rows(); ++i)
    {
      const double length = normals->row(i).norm();
      if(!std::isfinite(length) || !(length > 0))
        return invalid_normal_error(std::size_t(i));
      normals->row(i) /= length;
    }
  return {};
}

// The first point that coincides with another, which is then its nearest neighbour.
inline Input_error duplicate_error(const Points& X, const Point_neighbours& neighbours)
{
  for(std::size_t i = 0; i < neighbours.size(); ++i)
  {
    const Index j = *neighbours.begin(i);
    if(point(X, j) == point(X, i))
      return duplicate_points_error(i, j);
  }
  return {};
}

// The points far from all others, and those of no usable normal.
inline std::vector<bool> isolated_points(const Point_neighbours& neighbours, const Points& N)
{
  const std::size_t n = neighbours.size();
  std::vector<double> radii(n);
  for(std::size_t i = 0; i < n; ++i)
    radii[i] = neighbours.radius(i);
  std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(n / 2), radii.end());
  const double limit = isolated_radius_factor * radii[n / 2];
  std::vector<bool> isolated(n);
  for(std::size_t i = 0; i < n; ++i)
    isolated[i] = neighbours.radius(i) > limit || !(point(N, i).squaredNorm() > 0.5);
  return isolated;
}

} // namespace point_set_check

// The structure of the points X with their `normals` if given, `k` neighbours each.
inline Point_set_structure point_set_structure(const Points& X, std::optional<Points> normals, std::size_t k)
{
  namespace C = point_set_check;
  Point_set_structure s;
  const std::size_t n = std::size_t(X.rows());
  if(k < 3)
    s.error = invalid_number_of_neighbors_error(k);
  else if(Input_error error = C::value_error(X, normals))
    s.error = std::move(error);
  else if(n <= k)
    s.error = too_few_points_error(n, k);
  if(s.error)
    return s;
  const Point_neighbours neighbours(X, k);
  if((s.error = C::duplicate_error(X, neighbours)))
    return s;
  s.normals = normals ? std::move(*normals) : estimated_normals(X, neighbours);
  s.isolated = C::isolated_points(neighbours, s.normals);
  s.fans = tangent_fans(X, s.normals, neighbours, s.isolated);
  bool any_closed = false;
  for(std::size_t i = 0; i < n; ++i)
  {
    s.isolated[i] = s.isolated[i] || s.fans[i].triangles.empty();
    any_closed = any_closed || s.fans[i].is_closed();
  }
  if(!any_closed)
    s.error = no_surface_error();
  return s;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_CHECK_H
