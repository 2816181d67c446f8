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
// cross. Where a mean stalls (points of several sheets pressed together near a cell's centre),
// the points of the triangles still crossing then search their boxes one at a time
// (search_uncrossed_positions): a move never adds a crossing. Each moved point's box then
// shrinks to the largest one around it within the old. The first search for crossings is among
// the triangles with a point of a split cell (a cell of several points) only: the others, at the
// centres of their cells, are faces of the dual grid, which never cross; later ones among those
// that crossed or have a moved point.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_UNTANGLING_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_UNTANGLING_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Triangle_crossings.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <utility>
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

// The search after the rounds: the positions it tries for a point, a grid of
// untangling_grid + 1 per axis over its box less the room; the passes over the points of the
// triangles still crossing; and the angle, in degrees, under which it prefers wider triangles
// (the needles the barrier pushes back on label surfaces, Fairing_settings.h). On 100 maps of
// 14^3 random voxels of 3 to 6 labels, the rounds left 1,690 crossing triangles on 94 of them,
// the search 8 on 2; faired, the labels that cross themselves went from 150 to 3 and the
// smallest angles' geometric mean from 4.20 to 4.23 degrees (design notes).
constexpr int untangling_grid = 4;
constexpr std::size_t untangling_passes = 10;
constexpr double untangling_needle_angle = 6;

// The triangles whose `reach` (the box of each) meets each of `regions`, in increasing order.
inline std::vector<std::vector<std::size_t> > triangles_meeting(const std::vector<Bbox_3>& reach,
                                                                 const std::vector<Bbox_3>& regions)
{
  using Box = Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<Box> region_boxes, triangle_boxes;
  for(std::size_t r = 0; r < regions.size(); ++r)
    region_boxes.emplace_back(regions[r], r);
  for(std::size_t f = 0; f < reach.size(); ++f)
    triangle_boxes.emplace_back(reach[f], f);
  std::vector<std::vector<std::size_t> > meeting(regions.size());
  box_intersection_d<Sequential_tag>(region_boxes.begin(), region_boxes.end(), triangle_boxes.begin(),
                                     triangle_boxes.end(),
                                     [&meeting](const Box& r, const Box& f) { meeting[r.info()].push_back(f.info()); });
  for(auto& list : meeting)
    std::sort(list.begin(), list.end());
  return meeting;
}

// The triangles around point v.
inline Iterator_range<std::vector<std::size_t>::const_iterator> star(const Rows_by_vertex<std::size_t>& triangles_at,
                                                                    Index v)
{
  return make_range(triangles_at.begin(v), triangles_at.end(v));
}

// The search for one point's position in search_uncrossed_positions(): the position of a grid
// over its box [low, high] that leaves the fewest crossings between its triangles and those
// near; of those, the one whose triangles' smallest angle is largest, up to
// untangling_needle_angle; of those, the nearest. Its present position competes too, so that no
// move adds a crossing.
class Uncrossed_position_search
{
public:
  Uncrossed_position_search(Points& X, const std::vector<std::array<Index, 3> >& triangles,
                            const Rows_by_vertex<std::size_t>& triangles_at)
    : m_X(X), m_triangles(triangles), m_triangles_at(triangles_at),
      m_needle_sine(std::sin(untangling_needle_angle * CGAL_PI / 180))
  {
  }

  // Moves point v to its best position, judged against the triangles `near`; whether it moved.
  bool move(Index v, const std::vector<std::size_t>& near, const Points& low, const Points& high)
  {
    const Eigen::Vector3d start = point(m_X, v);
    // The triangles near without v, whose boxes stay as v moves.
    m_still.clear();
    for(std::size_t g : near)
      if(m_triangles[g][0] != v && m_triangles[g][1] != v && m_triangles[g][2] != v)
        m_still.emplace_back(g, box_of(g));
    auto best = score(v, start, (std::numeric_limits<int>::max)());
    Eigen::Vector3d best_position = start;
    for(int i = 0; i <= untangling_grid; ++i)
      for(int j = 0; j <= untangling_grid; ++j)
        for(int l = 0; l <= untangling_grid; ++l)
        {
          const int steps[3] = {i, j, l};
          for(int c = 0; c < 3; ++c)
            m_X(v, c) = low(v, c) + (high(v, c) - low(v, c)) * steps[c] / untangling_grid;
          const auto s = score(v, start, std::get<0>(best));
          if(s < best)
          {
            best = s;
            best_position = point(m_X, v);
          }
        }
    point(m_X, v) = best_position;
    return best_position != start;
  }

private:
  Bbox_3 box_of(std::size_t f) const
  {
    Bbox_3 b;
    for(Index v : m_triangles[f])
      b += Bbox_3(m_X(v, 0), m_X(v, 1), m_X(v, 2), m_X(v, 0), m_X(v, 1), m_X(v, 2));
    return b;
  }

  // Point v's present position: (crossings, minus the smallest sine up to the needle's, squared
  // distance from `start`), the smaller the better; the count stops once over `limit`, where the
  // position loses anyway. v's own triangles are boxed at each position.
  std::tuple<int, double, double> score(Index v, const Eigen::Vector3d& start, int limit)
  {
    int count = 0;
    double sine = m_needle_sine;
    m_moving.clear();
    for(std::size_t f : star(m_triangles_at, v))
      m_moving.emplace_back(f, box_of(f));
    for(std::size_t i = 0; i < m_moving.size(); ++i)
    {
      const std::size_t f = m_moving[i].first;
      const Bbox_3& b = m_moving[i].second;
      for(const auto& g : m_still)
        if(do_overlap(b, g.second) && Triangle_crossings::cross(m_X, m_triangles[f], m_triangles[g.first]))
          ++count;
      for(std::size_t j = i + 1; j < m_moving.size(); ++j) // each pair of v's own triangles once
        if(do_overlap(b, m_moving[j].second) &&
           Triangle_crossings::cross(m_X, m_triangles[f], m_triangles[m_moving[j].first]))
          ++count;
      if(count > limit)
        break;
      sine = (std::min)(sine, smallest_angle_sine(m_X, m_triangles[f]));
    }
    return std::make_tuple(count, -sine, (point(m_X, v) - start).squaredNorm());
  }

  Points& m_X;
  const std::vector<std::array<Index, 3> >& m_triangles;
  const Rows_by_vertex<std::size_t>& m_triangles_at;
  const double m_needle_sine;
  std::vector<std::pair<std::size_t, Bbox_3> > m_still, m_moving;
};

// The triangles that may meet each of `points`' triangles as the points move in their boxes
// (`reach`, the box of each triangle).
inline std::vector<std::vector<std::size_t> > triangles_near(const std::vector<Index>& points,
                                                             const Rows_by_vertex<std::size_t>& triangles_at,
                                                             const std::vector<Bbox_3>& reach)
{
  std::vector<Bbox_3> regions;
  for(Index v : points)
  {
    Bbox_3 region;
    for(std::size_t f : star(triangles_at, v))
      region += reach[f];
    regions.push_back(region);
  }
  return triangles_meeting(reach, regions);
}

// The points of the `crossing` triangles, one after the other, each moved by an
// Uncrossed_position_search within its box [low, high]. Passes while some cross and some point
// moves; `crossing` is updated and the moved points are marked in `moved`.
inline void search_uncrossed_positions(Points& X, const Points& low, const Points& high,
                                       const std::vector<std::array<Index, 3> >& triangles,
                                       const Triangle_crossings& crossings, std::vector<bool>& crossing,
                                       std::vector<bool>& moved)
{
  const std::size_t n = static_cast<std::size_t>(X.rows()), m = triangles.size();
  if(std::find(crossing.begin(), crossing.end(), true) == crossing.end())
    return;
  const Rows_by_vertex<std::size_t> triangles_at(n, [&](const auto& add) {
    for(std::size_t f = 0; f < m; ++f)
      for(Index v : triangles[f])
        add(v, f);
  });
  // Where each triangle can be while its points move in their boxes (every point is in its own).
  std::vector<Bbox_3> reach(m);
  for(std::size_t f = 0; f < m; ++f)
    for(Index v : triangles[f])
      reach[f] += Bbox_3(low(v, 0), low(v, 1), low(v, 2), high(v, 0), high(v, 1), high(v, 2));
  Uncrossed_position_search search(X, triangles, triangles_at);
  for(std::size_t pass = 0; pass < untangling_passes; ++pass)
  {
    std::vector<Index> points;
    for(std::size_t f = 0; f < m; ++f)
      if(crossing[f])
        points.insert(points.end(), triangles[f].begin(), triangles[f].end());
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if(points.empty())
      return;
    // A move is judged against all the triangles that may meet the point's as the points of the
    // pass move, so that it never adds a crossing.
    const std::vector<std::vector<std::size_t> > near = triangles_near(points, triangles_at, reach);
    bool any = false;
    for(std::size_t k = 0; k < points.size(); ++k)
      if(search.move(points[k], near[k], low, high))
        any = moved[points[k]] = true;
    if(!any)
      return;
    std::vector<bool> changed = crossing;
    for(Index v : points)
      for(std::size_t f : star(triangles_at, v))
        changed[f] = true;
    crossing = crossings.find(X, changed);
  }
}

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
  search_uncrossed_positions(X, low, high, local, crossings, crossing, moved_ever);

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
