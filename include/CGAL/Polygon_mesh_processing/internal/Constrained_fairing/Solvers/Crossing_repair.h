// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Crossings: two triangles of a soup that pass through each other. A promise, then how it is
// kept: the faired soup has no crossing that its input did not have. The bounds keep the points
// of a label map apart (label_surface_nets()), but not the triangles between them: where two
// sheets of a surface are pressed within their boxes (a ribbon one voxel thick, sheets that meet
// at a junction), a faired triangle may pass through another. The repair finds the crossing
// triangles (Triangle_crossings.h) and pulls their points halfway back towards where they
// started, round after round, a point that was pulled crossing_repair_rounds times all the way:
// the points end between where the descent left them and where they started, within their
// bounds, which are convex, and every crossing goes but those of triangles that crossed at the
// start already.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CROSSING_REPAIR_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CROSSING_REPAIR_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Triangle_crossings.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The halfway pulls of a point before it is pulled back all the way.
constexpr std::size_t crossing_repair_rounds = 6;

// Pulls the points of the triangles of X that cross, where they did not cross in X0, back
// towards X0 until none is left; returns the number of points pulled.
template <typename Bound>
std::size_t repair_crossings(const std::vector<std::array<Index, 3> >& triangles, const Bound& bound,
                             const std::vector<bool>& moving, const Points& X0, Points& X)
{
  const Triangle_crossings crossings(triangles);
  const std::size_t n = static_cast<std::size_t>(X.rows()), m = triangles.size();
  std::vector<std::size_t> pulls(n, 0);
  std::size_t pulled = 0;
  std::vector<bool> crossing = crossings.find(X, {}), known(m, false), inherited(m, false);
  for(;;)
  {
    // Which of the crossing triangles crossed at the start already: pulling them back cannot help.
    std::vector<bool> unknown(m, false);
    bool any = false;
    for(std::size_t f = 0; f < m; ++f)
      if(crossing[f] && !known[f])
        unknown[f] = known[f] = any = true;
    if(any)
    {
      const std::vector<bool> at_start = crossings.find(X0, unknown);
      for(std::size_t f = 0; f < m; ++f)
        inherited[f] = inherited[f] || (unknown[f] && at_start[f]);
    }
    std::vector<bool> moved(n, false);
    any = false;
    for(std::size_t f = 0; f < m; ++f)
      if(crossing[f] && !inherited[f])
        for(Index v : triangles[f])
          if(moving[v] && !moved[v] && pulls[v] <= crossing_repair_rounds)
          {
            moved[v] = any = true;
            pulled += pulls[v] == 0;
            ++pulls[v];
            const double keep = pulls[v] > crossing_repair_rounds ? 0 : 0.5;
            point(X, v) = point(X0, v) + keep * (point(X, v) - point(X0, v));
            bound.project(X, v);
          }
    if(!any)
      return pulled;
    // A triangle crosses now only if it crossed before or one of its points moved.
    std::vector<bool> changed(m, false);
    for(std::size_t f = 0; f < m; ++f)
      changed[f] = crossing[f] || moved[triangles[f][0]] || moved[triangles[f][1]] || moved[triangles[f][2]];
    crossing = crossings.find(X, changed);
  }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CROSSING_REPAIR_H
