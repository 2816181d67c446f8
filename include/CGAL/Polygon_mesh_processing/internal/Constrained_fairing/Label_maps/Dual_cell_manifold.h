// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether the labels' surfaces at a dual cell's points (Dual_cell.h) are as they must be: closed
// across the segments between the points, and passing each point once.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_MANIFOLD_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_MANIFOLD_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_nodes.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_points.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Whether each label's surface is closed across the segments between the cell's points: each
// segment that a face's corner, a cap or a bridge of the label runs along has two of them.
template <typename Label>
bool surfaces_closed(const Dual_cell_nodes<Label>& nodes, const Dual_cell_points<Label>& points)
{
  std::vector<std::pair<Label, std::array<int, 2> > > uses;
  const auto use = [&uses](Label l, int p, int q) {
    if(p != q)
      uses.push_back({l, {(std::min)(p, q), (std::max)(p, q)}});
  };
  for(int f = 0; f < 12; ++f)
    if(nodes.active(f))
      for(int side = 0; side < 2; ++side)
        use(nodes.label(voxel_of_face(f, side)), points.corner_points[std::size_t(f)][0],
            points.corner_points[std::size_t(f)][1]);
  for(const Dual_cell_cap<Label>& cap : points.caps)
    for(const Label l : cap.labels)
      for(std::size_t k = 0; k < 3; ++k)
        use(l, cap.points[k], cap.points[(k + 1) % 3]);
  for(const Dual_cell_bridge<Label>& bridge : points.bridges)
    for(const Label l : bridge.labels)
      use(l, bridge.points[0], bridge.points[1]);
  std::sort(uses.begin(), uses.end());
  for(std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i;
    while(j < uses.size() && uses[j] == uses[i])
      ++j;
    if(j - i != 2)
      return false;
    i = j;
  }
  return true;
}

// The arm of each node around its point: the dual edge out of the cell, the two nodes of a
// `doubled` ring (a bit per ring) at one point being one.
template <typename Label>
std::array<int, 12> arms_of_nodes(const Dual_cell_nodes<Label>& nodes, const Dual_cell_points<Label>& points,
                                  unsigned doubled)
{
  constexpr int none = Dual_cell_points<Label>::none;
  std::array<int, 12> arm_of_node;
  for(int v = 0; v < 12; ++v)
    arm_of_node[std::size_t(v)] = v;
  for(int ring = 0; ring < 6; ++ring)
    if((doubled >> ring) & 1u)
    {
      int at[2] = {none, none};
      for(int f = 0; f < 12; ++f)
        if(nodes.active(f))
          for(int axis = 0; axis < 3; ++axis)
            if(axis != f / 4 && nodes.node(f, axis) / 2 == ring)
              at[nodes.node(f, axis) % 2] = points.point(f, axis);
      if(at[0] == at[1])
        arm_of_node[std::size_t(2 * ring + 1)] = 2 * ring;
    }
  return arm_of_node;
}

// The wedges of label l's faces, caps and bridges around point p, each between two arms: a
// node's (arm_of_node), or 12 + another point of the cell, the segment to it.
template <typename Label>
void wedges_around(const Dual_cell_nodes<Label>& nodes, const Dual_cell_points<Label>& points,
                   const std::array<int, 12>& arm_of_node, Label l, int p, std::vector<std::array<int, 2> >& wedges)
{
  wedges.clear();
  nodes.for_each_side_of(l, [&](int f, int) {
    const std::array<int, 2> axes = Dual_cell_points<Label>::corner_axes(f);
    const int a = points.point(f, axes[0]), b = points.point(f, axes[1]);
    const int in = arm_of_node[std::size_t(nodes.node(f, axes[0]))],
              out = arm_of_node[std::size_t(nodes.node(f, axes[1]))];
    if(a == p)
      wedges.push_back({in, b == p ? out : 12 + b});
    else if(b == p)
      wedges.push_back({12 + a, out});
  });
  for(const Dual_cell_cap<Label>& cap : points.caps)
    if(cap.labels[0] == l || cap.labels[1] == l)
      for(std::size_t k = 0; k < 3; ++k)
        if(cap.points[k] == p)
          wedges.push_back({12 + cap.points[(k + 1) % 3], 12 + cap.points[(k + 2) % 3]});
  for(const Dual_cell_bridge<Label>& bridge : points.bridges)
    if(bridge.labels[0] == l || bridge.labels[1] == l)
      for(std::size_t k = 0; k < 2; ++k)
        if(bridge.points[k] == p)
          wedges.push_back({12 + bridge.points[1 - k], arm_of_node[std::size_t(nodes.node(bridge.faces[k], bridge.axis))]});
}

// Whether the wedges make one closed fan, or none: every arm in two wedges, all joined.
inline bool one_closed_fan(const std::vector<std::array<int, 2> >& wedges)
{
  std::array<int, 52> uses{}, parent; // 12 nodes, 40 points
  for(int x = 0; x < 52; ++x)
    parent[std::size_t(x)] = x;
  const auto root = [&parent](int x) { return root_in(parent, x); };
  for(const auto& w : wedges)
  {
    ++uses[std::size_t(w[0])], ++uses[std::size_t(w[1])];
    parent[std::size_t(root(w[0]))] = root(w[1]);
  }
  int fans = 0;
  for(int x = 0; x < 52; ++x)
  {
    if(uses[std::size_t(x)] != 0 && uses[std::size_t(x)] != 2)
      return false;
    fans += uses[std::size_t(x)] != 0 && root(x) == x;
  }
  return fans <= 1;
}

// Whether the surface of every label but `skip` passes each point of the cell once: around the
// point, the label's faces, caps and bridges make one fan closed on itself. A fan's arms are
// the dual edges out of the cell, by node, and the segments to the cell's other points; the two
// nodes of a `doubled` ring (a bit per ring) at one point are one dual edge.
template <typename Label>
bool manifold_at_points(const Dual_cell_nodes<Label>& nodes, const Dual_cell_points<Label>& points, Label skip,
                        unsigned doubled = 0)
{
  const std::array<int, 12> arm_of_node = arms_of_nodes(nodes, points, doubled);
  std::vector<std::array<int, 2> > wedges; // arms: node, or 12 + the other point
  for(const Label l : nodes.block_labels())
  {
    if(l == skip)
      continue;
    for(int p = 0; p < points.count; ++p)
    {
      wedges_around(nodes, points, arm_of_node, l, p, wedges);
      if(!one_closed_fan(wedges))
        return false;
    }
  }
  return true;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DUAL_CELL_MANIFOLD_H
