// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangles of a label map's surface nets, in this order: for each pair of neighbouring
// voxels a, b = a + e_axis with different labels, axis by axis and a in the order of the voxels,
// their face's polygon cut into triangles pointing from a into b (Face_cuts.h), the dead ends
// after all others; then the caps of the cells' ridges; then the bridges.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_TRIANGLES_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_TRIANGLES_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Face_cuts.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Label_grid.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Net_points.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The polygon of the face between voxels a and a + e_axis: the four dual cells around it,
// counterclockwise seen from a + e_axis, at each the face's corner, one point or two.
template <typename Label>
void face_polygon(const Label_grid<Label>& grid, const Net_points<Label>& net, int axis, const std::ptrdiff_t a[3],
                  Face_polygon& polygon)
{
  const int u = (axis + 1) % 3, w = (axis + 2) % 3; // (axis, u, w) is right-handed
  const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
  polygon.clear();
  for(int k = 0; k < 4; ++k)
  {
    std::ptrdiff_t q[3];
    q[axis] = a[axis] + 1;
    q[u] = a[u] + du[k];
    q[w] = a[w] + dw[k];
    const std::size_t index = grid.cell_index(q), base = net.first_point(index);
    const typename Net_points<Label>::Corners* corners = net.corners(index);
    if(!corners)
    {
      polygon.emplace_back(base, k);
      continue;
    }
    // In the block of cell q, voxel a has offsets (0, 1 - du, 1 - dw); the quad arrives at
    // corner k along u (k odd) or w and leaves along the other.
    const int face = 4 * axis + (1 - du[k]) + 2 * (1 - dw[k]);
    const int in = k % 2 == 1 ? 0 : 1;
    const std::size_t from = base + std::size_t((*corners)[std::size_t(2 * face + in)]),
                      to = base + std::size_t((*corners)[std::size_t(2 * face + 1 - in)]);
    polygon.emplace_back(from, k);
    if(to != from)
      polygon.emplace_back(to, k);
  }
}

// A bridge's triangle: its cell's two points and the point of the next cell along the ring's
// half-axis, where the ring's faces meet (that cell leaves the ring whole). Its normal points
// from the ring's voxel k into voxel k + 2 (the bridge's labels, in order) when the next cell is
// on the positive side, and the other way on the negative side: the ring runs counterclockwise
// around the axis, the points of the pairs around voxels k + 1 and k + 3.
template <typename Label>
Net_triangle bridge_triangle(const Label_grid<Label>& grid, const Net_points<Label>& net,
                             const typename Net_points<Label>::Cell_bridge& cell_bridge)
{
  const auto& [at, bridge] = cell_bridge;
  std::ptrdiff_t next[3] = {at[0], at[1], at[2]};
  next[bridge.axis] += bridge.side == 1 ? 1 : -1;
  const std::size_t here = net.first_point(grid.cell_index(at.data())), index = grid.cell_index(next);
  // The next cell's corner of a face of the ring: in its block, the face's voxels are on the
  // other side along the ring's axis.
  std::size_t there = net.first_point(index);
  if(const typename Net_points<Label>::Corners* corners = net.corners(index))
  {
    const int f = bridge.faces[0];
    const bool along_u = bridge.axis == (f / 4 + 1) % 3;
    there += std::size_t((*corners)[std::size_t(2 * (f ^ (along_u ? 1 : 2)) + (along_u ? 0 : 1))]);
  }
  std::array<std::size_t, 2> pair = {here + std::size_t(bridge.points[0]), here + std::size_t(bridge.points[1])};
  if(bridge.side == 0)
    std::swap(pair[0], pair[1]);
  return {pair[0], pair[1], there};
}

template <typename TriangleRange, typename LabelPairRange, typename Label>
void add_net_triangle(const Net_triangle& t, const std::array<Label, 2>& labels, TriangleRange& triangles,
                      LabelPairRange& face_labels)
{
  using Point_index = typename TriangleRange::value_type::value_type;
  triangles.push_back({Point_index(t[0]), Point_index(t[1]), Point_index(t[2])});
  face_labels.push_back(labels);
}

// Appends the triangles of the nets of `grid`, whose points `net` has made in `points`.
template <typename Label, typename PointRange, typename TriangleRange, typename LabelPairRange>
void make_net_triangles(const Label_grid<Label>& grid, const Net_points<Label>& net, const PointRange& points,
                        TriangleRange& triangles, LabelPairRange& face_labels)
{
  struct Dead_end
  {
    int axis;
    std::array<Label, 2> labels;
    Face_polygon face;
  };
  std::vector<Dead_end> dead_ends;
  Face_cuts<PointRange> cuts(points);
  Face_polygon polygon;
  for(int axis = 0; axis < 3; ++axis)
  {
    std::ptrdiff_t lo[3] = {0, 0, 0};
    lo[axis] = -1;
    std::ptrdiff_t a[3];
    for(a[0] = lo[0]; a[0] < grid.voxels(0); ++a[0])
      for(a[1] = lo[1]; a[1] < grid.voxels(1); ++a[1])
        for(a[2] = lo[2]; a[2] < grid.voxels(2); ++a[2])
        {
          std::ptrdiff_t b[3] = {a[0], a[1], a[2]};
          ++b[axis];
          const std::array<Label, 2> labels = {grid.label(a[0], a[1], a[2]), grid.label(b[0], b[1], b[2])};
          if(labels[0] == labels[1])
            continue;
          face_polygon(grid, net, axis, a, polygon);
          if(const std::optional<Face_cut> cut = cuts.cut(polygon))
          {
            for(const Net_triangle& t : *cut)
              add_net_triangle(t, labels, triangles, face_labels);
          }
          else
            dead_ends.push_back({axis, labels, polygon});
        }
  }
  for(const Dead_end& dead_end : dead_ends)
    for(const Net_triangle& t : cuts.cut_dead_end(dead_end.face, dead_end.axis))
      add_net_triangle(t, dead_end.labels, triangles, face_labels);
  for(const auto& cap : net.caps())
    add_net_triangle(cap.points, cap.labels, triangles, face_labels);
  for(const auto& bridge : net.bridges())
    add_net_triangle(bridge_triangle(grid, net, bridge), bridge.second.labels, triangles, face_labels);
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NET_TRIANGLES_H
