// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A dual cell's points (Dual_cell.h) as the corners of its faces: the point of each face next to
// each of its dual edges, numbered by the faces, and the triangles between the cell's points
// that close what the faces leave open, the caps of its ridges and the bridges of its split rings.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_POINTS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_POINTS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_nodes.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// A triangle that caps a cell's ridge, as points of the cell, with the labels on its two sides:
// the normal of (p, q, r) points from the region of the first label into the second's.
template <typename Label>
struct Dual_cell_cap
{
  std::array<int, 3> points;
  std::array<Label, 2> labels;
};

// A face that closes the gap of a split ring of four labels (Dual_cell_nodes::split()): a
// triangle of the cell's points of the ring's two pairs and the next cell's point along the
// ring's half-axis, between the labels of the two voxels that meet in the gap.
template <typename Label>
struct Dual_cell_bridge
{
  int axis, side;              // the ring's half-axis: side 1 towards the next cell along `axis`
  std::array<int, 2> points;   // the points of the faces around the ring's voxels k + 1 and k + 3
  std::array<int, 2> faces;    // a face of each pair
  std::array<Label, 2> labels; // of the ring's voxels k and k + 2
};

template <typename Label>
struct Dual_cell_points
{
  static constexpr int none = -1;

  Dual_cell_points()
  {
    for(std::array<int, 2>& points : corner_points)
      points.fill(none);
  }

  // The point of face f's corner next to its dual edge along `axis` (not f / 4); none where
  // face f has one label on both sides.
  int point(int f, int axis) const { return corner_points[std::size_t(f)][axis == (f / 4 + 1) % 3 ? 0 : 1]; }
  // Face f's corner as its polygon runs through it (face_polygon(), Net_triangles.h:
  // counterclockwise seen from its second voxel): from the point next to the edge it arrives by
  // to the one it leaves by.
  std::array<int, 2> corner(int f) const
  {
    const std::array<int, 2> axes = corner_axes(f);
    return {point(f, axes[0]), point(f, axes[1])};
  }
  // The axes of the dual edges it arrives by and leaves by.
  static std::array<int, 2> corner_axes(int f)
  {
    const int a = f / 4, u = (a + 1) % 3, w = (a + 2) % 3, o = voxel_of_face(f, 0);
    const int du = 1 - ((o >> u) & 1), dw = 1 - ((o >> w) & 1);
    const bool odd = du != dw; // corners 1 and 3 of (0, 0), (1, 0), (1, 1), (0, 1)
    return {odd ? u : w, odd ? w : u};
  }
  bool is_junction(int p) const { return first_junction != none && p >= first_junction; }

  // Each node's point: numbered 0, 1, ... by the first face (and its first corner) that has them.
  void number(const Dual_cell_nodes<Label>& nodes, const std::array<int, 12>& point_of_node)
  {
    std::array<int, 40> number;
    number.fill(-1);
    count = 0;
    for(int f = 0; f < 12; ++f)
    {
      if(!nodes.active(f))
        continue;
      for(int side = 0; side < 2; ++side)
      {
        const int axis = (f / 4 + 1 + side) % 3;
        int& n = number[std::size_t(point_of_node[std::size_t(nodes.node(f, axis))])];
        if(n < 0)
          n = count++;
        corner_points[std::size_t(f)][std::size_t(side)] = n;
      }
    }
    for(Dual_cell_bridge<Label>& bridge : bridges)
      for(std::size_t pair = 0; pair < 2; ++pair)
        bridge.points[pair] = point(bridge.faces[pair], bridge.axis);
  }
  // One point per sheet, no caps.
  void one_per_sheet(const Dual_cell_nodes<Label>& nodes, const std::array<int, 12>& sheet)
  {
    number(nodes, sheet);
    clear_caps();
  }
  void clear_caps()
  {
    caps.clear();
    first_junction = none;
  }
  // Point y becomes point x; the points after y are renumbered.
  void merge(int x, int y)
  {
    const auto renumber = [x, y](int& p) {
      if(p == y)
        p = x;
      else if(p > y)
        --p;
    };
    for(std::array<int, 2>& points : corner_points)
      for(int& p : points)
        renumber(p);
    --count;
  }

  int count = 0;
  // Of each face, the points next to its dual edges along (f / 4 + 1) % 3 and (f / 4 + 2) % 3.
  std::array<std::array<int, 2>, 12> corner_points;
  std::vector<Dual_cell_cap<Label> > caps;
  std::vector<Dual_cell_bridge<Label> > bridges;
  int first_junction = none; // the points from here on are apexes of caps, no corners of faces
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_POINTS_H
