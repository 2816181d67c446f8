// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points of split cells can line up (a staircase of cells split alike): the middle point of a
// triangle on a line moves off it by half its box along the axis the line runs least along, its
// box shrunk to the half it moved into. The fairing straightens such junction lines again, and
// the repair after it pulls the triangle back to this start: moved by a quarter of its box, a
// triangle of Debian's inia19 atlas stayed a 4.85-degree needle.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LINED_UP_POINTS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LINED_UP_POINTS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Net_points.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The rounds over the triangles, repeated while a point moves, for a move can line up another
// triangle of the point. Each move halves the point's box along an axis: the count bounds how
// far a box shrinks (to a sixteenth). Not tuned: on Debian's atlases, CGAL's liver and 600 maps
// of 4^3 to 14^3 random voxels of 2 to 6 labels, no point moved in the second round.
constexpr int lined_up_rounds = 4;

// Moves the middle point of triangle t off the line its points are on, if they are; whether it
// moved. `half_extents[first_box + p - first_point]`: point p's box.
template <typename PointRange, typename Triangle, typename BoxRange>
bool move_off_line(PointRange& points, const Triangle& t, BoxRange& half_extents, std::size_t first_point,
                   std::size_t first_box)
{
  using Point = typename PointRange::value_type;
  using Epick = Exact_predicates_inexact_constructions_kernel;
  const std::array<Epick::Point_3, 3> p = {net_point(points, std::size_t(t[0])), net_point(points, std::size_t(t[1])),
                                           net_point(points, std::size_t(t[2]))};
  if(!CGAL::collinear(p[0], p[1], p[2]))
    return false;
  int middle = 0;
  while(middle < 2 && (p[std::size_t((middle + 1) % 3)] - p[std::size_t(middle)]) *
                          (p[std::size_t((middle + 2) % 3)] - p[std::size_t(middle)]) > 0)
    ++middle;
  const Epick::Vector_3 line = p[std::size_t((middle + 2) % 3)] - p[std::size_t((middle + 1) % 3)];
  std::size_t axis = 0;
  for(std::size_t a = 1; a < 3; ++a)
    if(std::abs(line[int(a)]) < std::abs(line[int(axis)]))
      axis = a;
  const std::size_t v = std::size_t(t[std::size_t(middle)]);
  const double shift = half_extents[first_box + v - first_point][axis] / 2;
  double x[3] = {p[std::size_t(middle)].x(), p[std::size_t(middle)].y(), p[std::size_t(middle)].z()};
  x[axis] += shift;
  points[v] = Point(x[0], x[1], x[2]);
  half_extents[first_box + v - first_point][axis] -= shift;
  return true;
}

// Moves the points [first_point, ...) of `points`, with their boxes [first_box, ...) of
// `half_extents`, off the lines of the triangles [first_triangle, ...) of `triangles`.
template <typename PointRange, typename TriangleRange, typename BoxRange>
void move_lined_up_points(PointRange& points, const TriangleRange& triangles, BoxRange& half_extents,
                          const std::size_t first_point, const std::size_t first_triangle, const std::size_t first_box)
{
  for(int round = 0; round < lined_up_rounds; ++round)
  {
    bool moved = false;
    for(std::size_t t = first_triangle; t < triangles.size(); ++t)
      if(move_off_line(points, triangles[t], half_extents, first_point, first_box))
        moved = true;
    if(!moved)
      break;
  }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_LINED_UP_POINTS_H
