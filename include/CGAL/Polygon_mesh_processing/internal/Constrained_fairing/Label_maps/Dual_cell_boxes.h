// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The boxes of a dual cell's points (Dual_cell.h): the cell shrunk by `margin` (a fraction of
// the spacing) on every side for a cell of one point; with more, the half or whole of each axis
// that the quarters of its faces (inside the cell) cover, two points whose boxes meet cut apart,
// along the axis where their faces lie farthest apart, at the centre plane or, where both lie on
// one side of it, at the quarter plane; a junction takes an octant that no other box meets; and
// each box keeps `margin` from the planes that cut it. The boxes of different points never meet,
// so no two points can meet.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_BOXES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_BOXES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_nodes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_points.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Each point's box, relative to the cell's centre in spacings along each axis.
struct Dual_cell_boxes
{
  std::vector<std::array<double, 3> > low, high;
};

// A box along each axis: the quarters [first, last) of the cell it spans.
using Box_range = std::array<std::array<int, 2>, 3>;

inline bool boxes_meet(const Box_range& x, const Box_range& y)
{
  for(std::size_t c = 0; c < 3; ++c)
    if((std::max)(x[c][0], y[c][0]) >= (std::min)(x[c][1], y[c][1]))
      return false;
  return true;
}

// Cuts boxes x and y apart along the axis where their faces lie farthest apart, at the centre
// plane or in the middle of their common part; false where no axis can part them so.
inline bool cut_apart(Box_range& x, Box_range& y, const std::array<double, 3>& x_centroid,
                      const std::array<double, 3>& y_centroid, bool at_centre)
{
  int best = -1, plane = 2;
  double apart = -1;
  bool x_lower = true;
  for(std::size_t c = 0; c < 3; ++c)
  {
    const int t = at_centre ? 2 : ((std::max)(x[c][0], y[c][0]) + (std::min)(x[c][1], y[c][1])) / 2;
    const double d = y_centroid[c] - x_centroid[c];
    if(x[c][0] < t && t < y[c][1] && d >= 0 && d > apart)
      best = int(c), apart = d, x_lower = true, plane = t;
    if(y[c][0] < t && t < x[c][1] && -d > apart)
      best = int(c), apart = -d, x_lower = false, plane = t;
  }
  if(best < 0)
    return false;
  std::array<int, 2>& lower = x_lower ? x[std::size_t(best)] : y[std::size_t(best)];
  std::array<int, 2>& upper = x_lower ? y[std::size_t(best)] : x[std::size_t(best)];
  lower[1] = (std::min)(lower[1], plane);
  upper[0] = (std::max)(upper[0], plane);
  return true;
}

// Each point's range: the halves (bit 0 lower, bit 1 upper) of each axis its faces cover, and
// where they lie (`centroid`): the faces whose corner is the point alone, else all that touch it.
template <typename Label>
std::vector<Box_range> face_ranges(const Dual_cell_nodes<Label>& nodes, const Dual_cell_points<Label>& points,
                                   std::vector<std::array<double, 3> >& centroid)
{
  const std::size_t count = std::size_t(points.count);
  std::vector<std::array<int, 3> > halves(count, std::array<int, 3>{0, 0, 0});
  centroid.assign(count, std::array<double, 3>{0, 0, 0});
  std::vector<bool> alone(count, false);
  for(int f = 0; f < 12; ++f)
    if(nodes.active(f) && points.corner_points[std::size_t(f)][0] == points.corner_points[std::size_t(f)][1])
      alone[std::size_t(points.corner_points[std::size_t(f)][0])] = true;
  for(int f = 0; f < 12; ++f)
  {
    if(!nodes.active(f))
      continue;
    const int p = points.corner_points[std::size_t(f)][0], q = points.corner_points[std::size_t(f)][1];
    for(int side = 0; side < (p == q ? 1 : 2); ++side)
    {
      const int point = side == 0 ? p : q;
      if(alone[std::size_t(point)] != (p == q))
        continue;
      const int a = f / 4, o = voxel_of_face(f, 0);
      for(int c = 0; c < 3; ++c)
        if(c != a)
        {
          const int upper = (o >> c) & 1;
          halves[std::size_t(point)][std::size_t(c)] |= upper ? 2 : 1;
          centroid[std::size_t(point)][std::size_t(c)] += upper ? 1 : -1;
        }
    }
  }
  for(auto& h : halves)
    for(int& axis : h)
      if(axis == 0)
        axis = 3;
  if(count == 1)
    halves[0] = {3, 3, 3};
  std::vector<Box_range> range(count);
  for(std::size_t p = 0; p < count; ++p)
    for(std::size_t c = 0; c < 3; ++c)
      range[p][c] = {(halves[p][c] & 1) ? 0 : 2, (halves[p][c] & 2) ? 4 : 2};
  return range;
}

// Boxes that meet are cut apart, at the axis where the two lie farthest apart: at the centre
// plane where both reach across it, else (two points whose faces lie in one octant) in the
// middle of the part they share. The first two points (junctions aside) that neither cut
// parts, none where all are parted.
template <typename Label>
std::optional<std::array<int, 2> > cut_boxes_apart(const Dual_cell_points<Label>& points, std::vector<Box_range>& range,
                                                   const std::vector<std::array<double, 3> >& centroid)
{
  for(std::size_t x = 0; x < range.size(); ++x)
    for(std::size_t y = x + 1; y < range.size(); ++y)
    {
      if(points.is_junction(int(x)) || points.is_junction(int(y)) || !boxes_meet(range[x], range[y]))
        continue;
      if(!cut_apart(range[x], range[y], centroid[x], centroid[y], true) &&
         !cut_apart(range[x], range[y], centroid[x], centroid[y], false))
        return std::array<int, 2>{int(x), int(y)};
    }
  return std::nullopt;
}

// Junction j, which has no faces of its own, takes the octant of the cell that no other box
// meets (of the junctions, those placed before it), the one on the side of the points of its
// caps; false where every octant is taken.
template <typename Label>
bool place_junction(const Dual_cell_points<Label>& points, int j, std::vector<Box_range>& range,
                    const std::vector<std::array<double, 3> >& centroid)
{
  std::array<double, 3> around{0, 0, 0};
  for(const Dual_cell_cap<Label>& cap : points.caps)
    if(cap.points[0] == j)
      for(std::size_t k = 1; k < 3; ++k)
        for(std::size_t c = 0; c < 3; ++c)
          around[c] += centroid[std::size_t(cap.points[k])][c];
  bool found = false;
  double best_side = 0;
  for(int octant = 0; octant < 8; ++octant)
  {
    Box_range box;
    double side = 0;
    for(std::size_t c = 0; c < 3; ++c)
    {
      const bool upper = (octant >> c) & 1;
      box[c] = {upper ? 2 : 0, upper ? 4 : 2};
      side += upper ? around[c] : -around[c];
    }
    bool free = true;
    for(int p = 0; p < points.count && free; ++p)
      free = (p >= j && points.is_junction(p)) || !boxes_meet(box, range[std::size_t(p)]);
    if(free && (!found || side > best_side))
      range[std::size_t(j)] = box, best_side = side, found = true;
  }
  return found;
}

// Makes the boxes, merging two points that no cut parts; false, `boxes` as they were, where
// merged points would leave a cap's or a bridge's hole open or a junction finds no octant.
template <typename Label>
bool make_boxes(const Dual_cell_nodes<Label>& nodes, Dual_cell_points<Label>& points, double margin,
                Dual_cell_boxes& boxes)
{
  for(;;)
  {
    std::vector<std::array<double, 3> > centroid;
    std::vector<Box_range> range = face_ranges(nodes, points, centroid);
    if(const std::optional<std::array<int, 2> > unparted = cut_boxes_apart(points, range, centroid))
    {
      // Merged, the points of a cap or a bridge could coincide and leave its hole open.
      if(!points.caps.empty() || !points.bridges.empty())
        return false;
      points.merge((*unparted)[0], (*unparted)[1]);
      continue;
    }
    for(int j = points.first_junction; j != Dual_cell_points<Label>::none && j < points.count; ++j)
      if(!place_junction(points, j, range, centroid))
        return false;
    boxes.low.assign(range.size(), {});
    boxes.high.assign(range.size(), {});
    for(std::size_t p = 0; p < range.size(); ++p)
      for(std::size_t c = 0; c < 3; ++c)
      {
        boxes.low[p][c] = 0.25 * range[p][c][0] - 0.5 + margin;
        boxes.high[p][c] = 0.25 * range[p][c][1] - 0.5 - margin;
      }
    return true;
  }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_BOXES_H
