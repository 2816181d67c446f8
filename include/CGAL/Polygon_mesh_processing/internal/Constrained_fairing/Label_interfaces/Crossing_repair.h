// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Crossings: two triangles of a soup that pass through each other. A promise, then how it is kept:
// two triangles of the faired soup cross only where one of them crossed a triangle in the input,
// no triangle's smallest angle is under both interface_repair_angle (Fairing_settings.h) and its
// start's, and a triangle is folded (Folded_triangles.h) only where it was folded at the start.
// The bounds keep the points of a label map apart (label_surface_nets()), but not the triangles
// between them: where two sheets of a surface are pressed within their boxes (a ribbon one voxel
// thick, sheets that meet at a junction), a faired triangle may pass through another. The repair
// finds the crossing triangles (Triangle_crossings.h) and pulls their points halfway back towards
// where they started, round after round, a point pulled halfway crossing_repair_rounds times going
// all the way at its next pull: the points end between where the descent left them and where they
// started, within their bounds, which are convex, and every crossing goes but those of triangles
// that crossed at the start already (a triangle pulled back may still meet one of these, which
// stays). Needles are pulled back too: a point pulled while its neighbours stay can flatten a
// triangle around it into one (on the atlases of label_map_topology, every angle under 4 degrees
// came from such pulls), and where the bounds and the junction lines hold a needle against the
// barrier, the barrier leaves it between 4 and 6 degrees. Such a triangle has all its points
// pulled, so that it goes back towards its start as a whole, until its smallest angle is no longer
// under both, or it is its start. So are folds, with their neighbours: the pulls turn triangles
// over too, mostly where the start was not folded (on the atlases, 72 of 78 and 37 of 39 folds
// left on natbrainlab and inia19 without this), and a fold whose points and neighbours' points
// are all back at their start is the start's triangle.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CROSSING_REPAIR_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CROSSING_REPAIR_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Folded_triangles.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Triangle_crossings.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The halfway pulls of a point before it is pulled back all the way.
constexpr std::size_t crossing_repair_rounds = 6;

// Pulls back towards X0, until none is left, the points of the triangles of `mesh` that cross in X
// where they did not cross in X0; where `smallest_sine` > 0, also those of the needles, whose
// smallest angle's sine (smallest_angle_sine()) is under both `smallest_sine` and its sine in X0,
// and those of the triangles folded in X and not in X0, with their neighbours across the hinges.
// Returns the number of points pulled.
template <typename Bound>
std::size_t repair_crossings_needles_and_folds(const Hinge_mesh& mesh, const Bound& bound,
                                               const std::vector<bool>& moving, double smallest_sine,
                                               const Points& X0, Points& X)
{
  const std::vector<std::array<Index, 3> >& triangles = mesh.triangles;
  const Triangle_crossings crossings(triangles);
  const std::size_t n = static_cast<std::size_t>(X.rows()), m = triangles.size();
  // Where no point moved (no iteration), no triangle can cross that did not at the start: the
  // search over the whole soup would take seconds on a large map to find nothing to pull.
  bool any_moved = false;
  for(std::size_t v = 0; v < n && !any_moved; ++v)
    any_moved = point(X, v) != point(X0, v);
  if(!any_moved)
    return 0;
  std::vector<std::size_t> pulls(n, 0);
  std::size_t pulled = 0;
  std::vector<bool> crossing = crossings.find(X, {}), known(m, false), inherited(m, false), needle(m);
  std::vector<double> start_sine(m, 0.);
  if(smallest_sine > 0)
    for(std::size_t f = 0; f < m; ++f)
      start_sine[f] = smallest_angle_sine(X0, triangles[f]);
  // A triangle back at its start is never a needle, whatever the rounding of its sine.
  const auto is_needle = [&](std::size_t f) {
    const auto& t = triangles[f];
    if(!(smallest_sine > 0))
      return false;
    if(point(X, t[0]) == point(X0, t[0]) && point(X, t[1]) == point(X0, t[1]) && point(X, t[2]) == point(X0, t[2]))
      return false;
    const double sine = smallest_angle_sine(X, t);
    return sine < smallest_sine && sine < start_sine[f];
  };
  for(std::size_t f = 0; f < m; ++f)
    needle[f] = is_needle(f);
  std::vector<bool> folded_at_start(m, false), fold(m, false);
  const auto find_folds = [&]() {
    std::fill(fold.begin(), fold.end(), false);
    if(smallest_sine > 0)
      for(Index f : folded_triangles(mesh, X))
        fold[f] = !folded_at_start[f];
  };
  if(smallest_sine > 0)
    for(Index f : folded_triangles(mesh, X0))
      folded_at_start[f] = true;
  find_folds();
  const auto pullable = [&](Index v) { return moving[v] && pulls[v] <= crossing_repair_rounds; };
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
    const auto pull = [&](std::size_t f) {
      for(Index v : triangles[f])
        if(pullable(v) && !moved[v])
          moved[v] = any = true;
    };
    for(std::size_t f = 0; f < m; ++f)
      if((crossing[f] && !inherited[f]) || needle[f])
        pull(f);
    for(const Hinge& h : mesh.hinges)
      if(fold[h.f[0]] || fold[h.f[1]])
        pull(h.f[0]), pull(h.f[1]);
    if(!any)
      return pulled;
    std::vector<bool> changed(m, false);
    for(std::size_t f = 0; f < m; ++f)
      changed[f] = moved[triangles[f][0]] || moved[triangles[f][1]] || moved[triangles[f][2]];
    for(std::size_t v = 0; v < n; ++v)
      if(moved[v])
      {
        pulled += pulls[v] == 0;
        ++pulls[v];
        const double keep = pulls[v] > crossing_repair_rounds ? 0 : 0.5;
        point(X, v) = point(X0, v) + keep * (point(X, v) - point(X0, v));
        bound.project(X, v);
      }
    for(std::size_t f = 0; f < m; ++f)
      needle[f] = changed[f] && is_needle(f);
    find_folds();
    // A triangle crosses now only if it crossed before or one of its points moved.
    for(std::size_t f = 0; f < m; ++f)
      changed[f] = changed[f] || crossing[f];
    crossing = crossings.find(X, changed);
  }
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CROSSING_REPAIR_H
