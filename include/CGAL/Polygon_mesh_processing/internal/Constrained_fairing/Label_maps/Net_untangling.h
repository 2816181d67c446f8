// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The untangling of a label map's surface nets. A promise, then how it is kept: every point
// stays in the box it had (up to rounding), and the nets cross (Triangle_crossings.h) only where
// moving points within those boxes did not part them. Points of split cells at the centres of
// their boxes (Dual_cell.h) can fold a triangle onto its neighbour or through another, and a
// crossing of the unfaired nets is one that neither the fairing nor the crossing repair, which
// pulls towards the start, can undo; points that end or branch a junction line even stay where
// they start. So the points of crossing triangles (from the second round on, with their
// neighbours) move to the mean of their neighbours (Neighbour_mean, Mesh_operators.h), clamped
// to the boxes they had less untangling_room, round after round (untangling_rounds) while some
// cross; each moved point's box then shrinks to the largest one around it within the old. The
// first search is among the triangles with a point of a split cell (a cell of several points)
// only: the others, at the centres of their cells, are faces of the dual grid, which never
// cross; later ones among those that crossed or have a moved point.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_UNTANGLING_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_UNTANGLING_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Triangle_crossings.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// On the atlases of Debian's mricron-data, the crossing triangles of the nets went from 463 to 13
// (inia19) and from 156 to 3 (natbrainlab); a trial of the first round's moves alone, without the
// room, reached in two rounds what it reached in 64.
constexpr std::size_t untangling_rounds = 8;
// What a moved point keeps of its box's half-extent at least, so that it can still move along
// every axis (a quarter left 26 crossing triangles on natbrainlab, nothing left boxes of no
// extent).
constexpr double untangling_room = 0.125;

// Untangles the points [first_point, ...) of `points` with their boxes [first_box, ...) of
// `half_extents`, the triangles [first_triangle, ...) of `triangles` indexing them;
// `split[p]`: point first_point + p is one of a split cell's.
template <typename PointRange, typename TriangleRange, typename BoxRange>
void untangle_nets(PointRange& points, const TriangleRange& triangles, BoxRange& half_extents,
                   const std::size_t first_point, const std::size_t first_triangle, const std::size_t first_box,
                   const std::vector<bool>& split)
{
  using Point = typename PointRange::value_type;
  if(std::find(split.begin(), split.end(), true) == split.end())
    return;
  const std::size_t n = points.size() - first_point, m = triangles.size() - first_triangle;
  std::vector<std::array<Index, 3> > local(m);
  std::vector<bool> changed(m, false);
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      local[f][k] = Index(std::size_t(triangles[first_triangle + f][k]) - first_point);
      if(split[local[f][k]])
        changed[f] = true;
    }
  Points X(static_cast<Eigen::Index>(n), 3), low(static_cast<Eigen::Index>(n), 3), high(static_cast<Eigen::Index>(n), 3);
  for(std::size_t p = 0; p < n; ++p)
    for(int c = 0; c < 3; ++c)
    {
      X(p, c) = CGAL::to_double(points[first_point + p][c]);
      const double room = untangling_room * half_extents[first_box + p][std::size_t(c)];
      low(p, c) = X(p, c) - half_extents[first_box + p][std::size_t(c)] + room;
      high(p, c) = X(p, c) + half_extents[first_box + p][std::size_t(c)] - room;
    }

  const Triangle_crossings crossings(local);
  std::vector<bool> crossing = crossings.find(X, changed), moved_ever(n, false);
  for(std::size_t round = 0; round < untangling_rounds; ++round)
  {
    std::vector<bool> moved(n, false);
    bool any = false;
    for(std::size_t f = 0; f < m; ++f)
      if(crossing[f])
        for(Index v : local[f])
          moved[v] = moved_ever[v] = any = true;
    if(!any)
      break;
    // From the second round on, the points around them too: a fold that the first round left is
    // held by neighbours that did not move.
    if(round > 0)
    {
      std::vector<bool> around = moved;
      for(const auto& t : local)
        if(moved[t[0]] || moved[t[1]] || moved[t[2]])
          for(Index v : t)
            around[v] = moved_ever[v] = true;
      moved.swap(around);
    }
    Neighbour_mean neighbours(local, n, [&moved](std::size_t v) { return bool(moved[v]); });
    neighbours.gather(X);
    for(std::size_t v = 0; v < n; ++v)
      if(moved[v])
        point(X, v) = neighbours.mean(v).cwiseMax(point(low, v)).cwiseMin(point(high, v));
    for(std::size_t f = 0; f < m; ++f)
      changed[f] = crossing[f] || moved[local[f][0]] || moved[local[f][1]] || moved[local[f][2]];
    crossing = crossings.find(X, changed);
  }

  for(std::size_t v = 0; v < n; ++v)
    if(moved_ever[v])
    {
      points[first_point + v] = Point(X(v, 0), X(v, 1), X(v, 2));
      for(int c = 0; c < 3; ++c)
        half_extents[first_box + v][std::size_t(c)] =
          (std::min)(X(v, c) - low(v, c), high(v, c) - X(v, c)) + untangling_room * half_extents[first_box + v][std::size_t(c)];
    }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_UNTANGLING_H
