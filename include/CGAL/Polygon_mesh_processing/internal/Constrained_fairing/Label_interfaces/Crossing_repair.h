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

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_interfaces/Triangle_crossings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Folded_triangles.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

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

// The pulls back of repair_crossings_needles_and_folds() below, round by round.
template <typename Bound>
class Crossing_repair
{
public:
  Crossing_repair(const Hinge_mesh& mesh, const Bound& bound, const std::vector<bool>& moving, double smallest_sine,
                  const Points& X0, Points& X)
    : m_mesh(mesh), m_triangles(mesh.triangles), m_bound(bound), m_moving(moving), m_smallest_sine(smallest_sine),
      m_X0(X0), m_X(X), m_crossings(mesh.triangles), m_n(static_cast<std::size_t>(X.rows())), m_m(m_triangles.size()),
      m_pulls(m_n, 0), m_known(m_m, false), m_inherited(m_m, false), m_needle(m_m), m_start_sine(m_m, 0.),
      m_folded_at_start(m_m, false), m_fold(m_m, false)
  {}

  // The number of points pulled.
  std::size_t run()
  {
    // Where no point moved (no iteration), no triangle can cross that did not at the start: the
    // search over the whole soup would take seconds on a large map to find nothing to pull.
    bool any_moved = false;
    for(std::size_t v = 0; v < m_n && !any_moved; ++v)
      any_moved = point(m_X, v) != point(m_X0, v);
    if(!any_moved)
      return 0;
    m_crossing = m_crossings.find(m_X, {});
    if(m_smallest_sine > 0)
      for(std::size_t f = 0; f < m_m; ++f)
        m_start_sine[f] = smallest_angle_sine(m_X0, m_triangles[f]);
    for(std::size_t f = 0; f < m_m; ++f)
      m_needle[f] = is_needle(f);
    if(m_smallest_sine > 0)
      for(Index f : folded_triangles(m_mesh, m_X0))
        m_folded_at_start[f] = true;
    find_folds();
    for(;;)
    {
      mark_inherited();
      std::vector<bool> moved(m_n, false);
      if(!select(moved))
        return m_pulled;
      pull_back(moved);
    }
  }

private:
  // A triangle back at its start is never a needle, whatever the rounding of its sine.
  bool is_needle(std::size_t f) const
  {
    const auto& t = m_triangles[f];
    if(!(m_smallest_sine > 0))
      return false;
    if(point(m_X, t[0]) == point(m_X0, t[0]) && point(m_X, t[1]) == point(m_X0, t[1]) &&
       point(m_X, t[2]) == point(m_X0, t[2]))
      return false;
    const double sine = smallest_angle_sine(m_X, t);
    return sine < m_smallest_sine && sine < m_start_sine[f];
  }

  void find_folds()
  {
    std::fill(m_fold.begin(), m_fold.end(), false);
    if(m_smallest_sine > 0)
      for(Index f : folded_triangles(m_mesh, m_X))
        m_fold[f] = !m_folded_at_start[f];
  }

  // Which of the crossing triangles crossed at the start already: pulling them back cannot help.
  void mark_inherited()
  {
    std::vector<bool> unknown(m_m, false);
    bool any = false;
    for(std::size_t f = 0; f < m_m; ++f)
      if(m_crossing[f] && !m_known[f])
        unknown[f] = m_known[f] = any = true;
    if(!any)
      return;
    const std::vector<bool> at_start = m_crossings.find(m_X0, unknown);
    for(std::size_t f = 0; f < m_m; ++f)
      m_inherited[f] = m_inherited[f] || (unknown[f] && at_start[f]);
  }

  // The points of this round's pulls: those of the new crossings, the needles and the folds with
  // their neighbours; false if there are none.
  bool select(std::vector<bool>& moved) const
  {
    bool any = false;
    const auto pull = [&](std::size_t f) {
      for(Index v : m_triangles[f])
        if(m_moving[v] && m_pulls[v] <= crossing_repair_rounds && !moved[v])
          moved[v] = any = true;
    };
    for(std::size_t f = 0; f < m_m; ++f)
      if((m_crossing[f] && !m_inherited[f]) || m_needle[f])
        pull(f);
    for(const Hinge& h : m_mesh.hinges)
      if(m_fold[h.f[0]] || m_fold[h.f[1]])
        pull(h.f[0]), pull(h.f[1]);
    return any;
  }

  // Halfway back at each of a point's first pulls, all the way at the last; then what changed.
  void pull_back(const std::vector<bool>& moved)
  {
    std::vector<bool> changed(m_m, false);
    for(std::size_t f = 0; f < m_m; ++f)
      changed[f] = moved[m_triangles[f][0]] || moved[m_triangles[f][1]] || moved[m_triangles[f][2]];
    for(std::size_t v = 0; v < m_n; ++v)
      if(moved[v])
      {
        m_pulled += m_pulls[v] == 0;
        ++m_pulls[v];
        const double keep = m_pulls[v] > crossing_repair_rounds ? 0 : 0.5;
        point(m_X, v) = point(m_X0, v) + keep * (point(m_X, v) - point(m_X0, v));
        m_bound.project(m_X, v);
      }
    for(std::size_t f = 0; f < m_m; ++f)
      m_needle[f] = changed[f] && is_needle(f);
    find_folds();
    // A triangle crosses now only if it crossed before or one of its points moved.
    for(std::size_t f = 0; f < m_m; ++f)
      changed[f] = changed[f] || m_crossing[f];
    m_crossing = m_crossings.find(m_X, changed);
  }

  const Hinge_mesh& m_mesh;
  const std::vector<std::array<Index, 3> >& m_triangles;
  const Bound& m_bound;
  const std::vector<bool>& m_moving;
  const double m_smallest_sine;
  const Points& m_X0;
  Points& m_X;
  const Triangle_crossings m_crossings;
  const std::size_t m_n, m_m;
  std::vector<std::size_t> m_pulls; // per point
  std::size_t m_pulled = 0;
  std::vector<bool> m_crossing, m_known, m_inherited, m_needle; // per triangle
  std::vector<double> m_start_sine;
  std::vector<bool> m_folded_at_start, m_fold;
};

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
  return Crossing_repair<Bound>(mesh, bound, moving, smallest_sine, X0, X).run();
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CROSSING_REPAIR_H
