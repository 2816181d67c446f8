// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far the surface still moves across itself: the stopping rule's measure of the shape
// (Stopping_rule.h). At the end of each window of iterations, the RMS over the vertices of
// each one's displacement since the window began, relative to its bound's size; what is left
// to move is extrapolated from the last two windows as the energy's remainder is.
//
// Why only the vertices on normal offsets count: there a displacement is along the normal of
// the smoothed start (Normal_offsets.h), the surface's own motion. A vertex that moves freely in
// its set (every vertex of a sliding run; folded starts and junction points among the offsets)
// keeps moving along the surface long after the shape has settled, so it is left out; where
// none counts, the shape has settled and the energy alone judges.
//
// The window's start is kept in single precision, relative to the input points: each
// coordinate of X - X0 is within the bound's size, so its rounding is 1e-7 of that size
// whatever the mesh's coordinates are.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SURFACE_MOTION_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SURFACE_MOTION_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Normal_offsets.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Stopping_rule.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Whether vertex i's displacement is not its motion across the surface: a vertex that moves
// freely in its set, as all do outside the normal offsets.
template <typename Bound>
bool moves_freely(const Bound&, std::size_t)
{
  return true;
}

template <typename Bound>
bool moves_freely(const Normal_offset_bound<Bound>& bound, std::size_t i)
{
  return bound.is_free(i);
}

class Surface_motion
{
public:
  // Ends a window at X (the first call starts the first one).
  template <typename Bound>
  void end_window(const Bound& bound, const Points& X)
  {
    const Points& X0 = bound.input_points();
    const std::size_t n = static_cast<std::size_t>(X.rows());
    const bool first = !m_started;
    if(first)
    {
      m_started = true;
      for(std::size_t i = 0; i < n; ++i)
        m_counted += counts(bound, i) ? 1 : 0;
      if(m_counted == 0)
      {
        m_last = 0; // nothing to wait for, and nothing kept
        return;
      }
      m_start.resize(X.rows(), 3);
    }
    if(m_counted == 0)
      return;
    const double squares = parallel_sum(n, m_partial, [&](std::size_t begin, std::size_t end) {
      double sum = 0;
      for(std::size_t i = begin; i < end; ++i)
      {
        const auto row = static_cast<Eigen::Index>(i);
        const Eigen::Vector3f offset = (point(X, i) - point(X0, i)).cast<float>();
        if(!first && counts(bound, i))
          sum += ((offset - m_start.row(row).transpose()).cast<double>() / bound.size(i)).squaredNorm();
        m_start.row(row) = offset.transpose();
      }
      return sum;
    });
    if(first)
      return;
    m_previous = m_last;
    m_last = std::sqrt(squares / double(m_counted));
  }

  // Whether what is left to move, extrapolated from the last two windows (a window that moved
  // m, q times the one before, leaves m q / (1 - q)), is at most `fraction` of the bounds'
  // sizes (RMS); a window that moved nothing has settled.
  bool has_settled(double fraction) const
  {
    if(m_last == 0)
      return true;
    return m_previous > 0 && remainder_is_small(m_last, m_previous, fraction);
  }

  // The RMS motion of the last window, relative to the bounds' sizes (negative before the first
  // window ends; 0 where no vertex counts).
  double last_window() const { return m_last; }

private:
  template <typename Bound>
  static bool counts(const Bound& bound, std::size_t i)
  {
    return bound.size(i) > 0 && !moves_freely(bound, i);
  }

  bool m_started = false;
  Float_points m_start;       // X - X0 at the window's start
  std::size_t m_counted = 0; // vertices whose motion counts
  double m_last = -1, m_previous = -1;
  std::vector<double> m_partial;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SURFACE_MOTION_H
