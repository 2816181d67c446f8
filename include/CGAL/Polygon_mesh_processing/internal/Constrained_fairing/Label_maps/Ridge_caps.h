// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The caps of the holes that a dual cell's ridge leaves (Dual_cell.h), where a face's corner is
// two points: fans of triangles of one interface where the holes border one, else fans around
// a new point, a junction; and, for a cell with a ball at its centre, each other label's holes
// capped against the ball.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_RIDGE_CAPS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_RIDGE_CAPS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Dual_cell_manifold.h>
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

// The holes of label l: the segments its faces use once, run with the label on their left seen
// from outside, followed head to tail into loops of points; false where a point is passed twice
// (the label would touch itself there).
template <typename Label>
bool hole_loops(const Dual_cell_nodes<Label>& nodes, const Dual_cell_points<Label>& points, Label l,
                std::vector<std::vector<int> >& loops)
{
  constexpr int none = Dual_cell_points<Label>::none;
  std::vector<std::array<int, 2> > once;
  nodes.for_each_side_of(l, [&](int f, int voxel) {
    std::array<int, 2> e = points.corner(f);
    if(voxel == voxel_of_face(f, 1))
      std::swap(e[0], e[1]); // the polygon runs counterclockwise seen from the other side
    if(e[0] == e[1])
      return;
    const auto reverse = std::find(once.begin(), once.end(), std::array<int, 2>{e[1], e[0]});
    if(reverse != once.end())
      once.erase(reverse);
    else
      once.push_back(e);
  });
  // Each point of a hole is left once and reached once, so the segments make loops.
  std::array<int, 40> out, in;
  out.fill(none);
  in.fill(0);
  for(std::size_t s = 0; s < once.size(); ++s)
  {
    if(out[std::size_t(once[s][0])] != none)
      return false;
    out[std::size_t(once[s][0])] = int(s);
    ++in[std::size_t(once[s][1])];
  }
  for(int p = 0; p < 40; ++p)
    if(in[std::size_t(p)] != (out[std::size_t(p)] != none ? 1 : 0))
      return false;
  loops.clear();
  std::vector<bool> used(once.size(), false);
  for(std::size_t first = 0; first < once.size(); ++first)
    if(!used[first])
    {
      loops.emplace_back();
      for(std::size_t s = first; !used[s]; s = std::size_t(out[std::size_t(once[s][1])]))
      {
        used[s] = true;
        loops.back().push_back(once[s][0]);
      }
    }
  return true;
}

// Where the holes border several interfaces: each label's holes are the segments its faces use
// once, run with the label on their left seen from outside, and each must be the reverse of one
// other label's. The holes of a label make loops (a point that two of them pass would pinch the
// label); loops that share segments make a group, and each group gets a new point, a junction,
// the apex of a fan of caps, one per segment, between the two labels whose holes run along it.
// Two loops of one label in a group would touch at its junction: no caps then.
template <typename Label>
bool cap_around_junctions(const Dual_cell_nodes<Label>& nodes, Dual_cell_points<Label>& points)
{
  constexpr int none = Dual_cell_points<Label>::none;
  struct Hole_segment
  {
    std::array<int, 2> ends;
    Label label;
    int loop;
  };
  std::vector<Hole_segment> holes;
  std::vector<Label> loop_label;
  std::vector<std::vector<int> > loops;
  for(const Label l : nodes.block_labels())
  {
    if(!hole_loops(nodes, points, l, loops))
      return false;
    for(const std::vector<int>& loop_points : loops)
    {
      const int loop = int(loop_label.size());
      loop_label.push_back(l);
      for(std::size_t k = 0; k < loop_points.size(); ++k)
        holes.push_back({{loop_points[k], loop_points[(k + 1) % loop_points.size()]}, l, loop});
    }
  }
  // The groups of loops, joined through the segments they share.
  std::vector<int> group(loop_label.size());
  for(std::size_t k = 0; k < group.size(); ++k)
    group[k] = int(k);
  const auto root = [&group](int k) { return root_in(group, k); };
  std::vector<Label> across(holes.size());
  for(std::size_t h = 0; h < holes.size(); ++h)
  {
    int count = 0;
    for(const Hole_segment& g : holes)
    {
      if(g.ends == holes[h].ends && &g != &holes[h])
        return false;
      if(g.ends[0] == holes[h].ends[1] && g.ends[1] == holes[h].ends[0])
      {
        ++count;
        across[h] = g.label;
        group[std::size_t(root(holes[h].loop))] = root(g.loop);
      }
    }
    if(count != 1)
      return false;
  }
  // One junction per group, numbered after the points.
  std::vector<int> junction(group.size(), none);
  int junctions = 0;
  for(std::size_t k = 0; k < group.size(); ++k)
  {
    int& j = junction[std::size_t(root(int(k)))];
    if(j == none)
      j = points.count + junctions++;
    for(std::size_t other = 0; other < k; ++other)
      if(loop_label[other] == loop_label[k] && root(int(other)) == root(int(k)))
        return false;
  }
  for(std::size_t h = 0; h < holes.size(); ++h)
    if(holes[h].label < across[h])
      points.caps.push_back({{junction[std::size_t(root(holes[h].loop))], holes[h].ends[1], holes[h].ends[0]},
                             {holes[h].label, across[h]}});
  points.first_junction = points.count;
  points.count += junctions;
  return true;
}

// Whether each label's surface stays closed across the segments where a face's corner is two
// points: two of its faces or bridges on each segment, or else, where the faces on segments are
// all of one interface, the holes the faces leave (the segments each used once) capped by
// triangles of that interface fanned around each loop. The caps follow the faces only, so a
// cell with bridges that needs caps does not close (Dual_cell::place_with_bridges() checks
// again).
template <typename Label>
bool close_ridges(const Dual_cell_nodes<Label>& nodes, Dual_cell_points<Label>& points)
{
  points.caps.clear();
  if(surfaces_closed(nodes, points))
    return true;
  std::vector<std::array<int, 2> > once; // directed from the smaller label into the larger
  bool one_interface = true;
  std::array<Label, 2> interface{};
  for(int f = 0; f < 12; ++f)
  {
    if(!nodes.active(f))
      continue;
    std::array<int, 2> e = points.corner(f);
    if(e[0] == e[1])
      continue;
    std::array<Label, 2> sides = {nodes.label(voxel_of_face(f, 0)), nodes.label(voxel_of_face(f, 1))};
    if(sides[1] < sides[0])
      std::swap(sides[0], sides[1]), std::swap(e[0], e[1]);
    one_interface = one_interface && (once.empty() || sides == interface);
    interface = sides;
    const auto reverse = std::find(once.begin(), once.end(), std::array<int, 2>{e[1], e[0]});
    if(reverse != once.end())
      once.erase(reverse);
    else
      once.push_back(e);
  }
  if(once.empty())
    return true;
  if(!one_interface)
    return cap_around_junctions(nodes, points);
  // The holes' loops: each segment used once, followed head to tail; the cap runs against them.
  while(!once.empty())
  {
    std::vector<int> loop = {once.front()[1], once.front()[0]};
    once.erase(once.begin());
    while(loop.back() != loop.front())
    {
      const auto next = std::find_if(once.begin(), once.end(),
                                     [&](const std::array<int, 2>& e) { return e[1] == loop.back(); });
      if(next == once.end())
        return false;
      loop.push_back((*next)[0]);
      once.erase(next);
    }
    loop.pop_back();
    for(std::size_t k = 1; k + 1 < loop.size(); ++k)
      points.caps.push_back({{loop[0], loop[k], loop[k + 1]}, interface});
  }
  return true;
}

// The holes of every label but `ball`'s capped between it and the ball, fanned around each
// loop; false where a label's holes pass a point twice.
template <typename Label>
bool cap_against_ball(const Dual_cell_nodes<Label>& nodes, Dual_cell_points<Label>& points, Label ball)
{
  std::vector<std::vector<int> > loops;
  for(const Label l : nodes.block_labels())
    if(l != ball)
    {
      if(!hole_loops(nodes, points, l, loops))
        return false;
      for(const std::vector<int>& loop : loops)
        for(std::size_t k = 1; k + 1 < loop.size(); ++k)
          points.caps.push_back({{loop[0], loop[k + 1], loop[k]}, {l, ball}});
    }
  return true;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_RIDGE_CAPS_H
