// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Curves made of edges of the surface (a mesh's creases, a multi-label surface's junction lines),
// told apart by their points' degrees alone: a point on exactly two of the edges is an inner
// point of its curve, faired as a curve (Curve_bending.h); a point on one edge (a curve's end)
// or on three or more (a corner, a branch) is an end, which no curve term holds.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CURVE_NETWORK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CURVE_NETWORK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Curve_network
{
  std::vector<bool> on_curve; // on one edge of the curves or more
  std::vector<bool> end;      // on one edge, or on three or more, or as the caller said
  std::vector<std::array<Index, 3> > inner; // {p, i, n}: inner point i and its neighbours, by i

  // `edges`: pairs of points in [0, n), each once; `also_end(i)`: whether a point on two edges
  // ends its curve anyway (where four labels meet).
  template <typename AlsoEnd>
  Curve_network(std::size_t n, const std::vector<std::array<Index, 2> >& edges, const AlsoEnd& also_end)
    : on_curve(n, false), end(n, false)
  {
    std::vector<std::vector<Index> > neighbours(n);
    for(const auto& e : edges)
    {
      neighbours[e[0]].push_back(e[1]);
      neighbours[e[1]].push_back(e[0]);
    }
    for(std::size_t v = 0; v < n; ++v)
    {
      const std::size_t degree = neighbours[v].size();
      on_curve[v] = degree > 0;
      end[v] = (degree != 0 && degree != 2) || also_end(v);
      if(degree == 2 && !end[v])
        inner.push_back({neighbours[v][0], Index(v), neighbours[v][1]});
    }
  }

  Curve_network(std::size_t n, const std::vector<std::array<Index, 2> >& edges)
    : Curve_network(n, edges, [](std::size_t) { return false; })
  {}

  // No curve.
  Curve_network() = default;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CURVE_NETWORK_H
