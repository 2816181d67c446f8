// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the settings and the per-vertex maps ask of each vertex that takes part in the fairing,
// once the input check (Value_check.h) accepted it, read and turned into the solver's Ball_bound
// or Box_bound, which holds it from then on:
//  - its tolerance t_i = min(epsilon, vertex_tolerance_map(v)), or 0 for a fixed vertex;
//  - for the box, its half-extents min(t_i, H_i) per axis, H_i from vertex_box_half_extents_map
//    or box_half_extents (t_i alone without them), around vertex_box_center_map(v) or the
//    input position (always the input position for a vertex of tolerance 0, which so stays
//    where it is).
// epsilon thus caps every size, and a fixed vertex's coordinates come out bit-identical.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BOUND_PARAMETERS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BOUND_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Bound_parameters
{
public:
  // Reads what `maps` ask of the vertices of `part`, which the input check (Value_check.h)
  // accepted, storing vertex k of the part at rank[k], its place in the solver's order; `box`:
  // whether the bound is the box, whose half-extents are `uniform_extents` where `maps` give
  // none (infinite: the tolerance alone).
  template <typename Part, typename VertexMaps>
  Bound_parameters(const Part& part, const std::vector<Index>& rank, double epsilon, bool box,
                   const std::array<double, 3>& uniform_extents, const VertexMaps& maps)
    : m_box(box), m_epsilon(epsilon), m_uniform_extents(uniform_extents[0], uniform_extents[1], uniform_extents[2])
  {
    const std::size_t n = part.size();
    bool any_fixed = false;
    for(std::size_t k = 0; k < n; ++k)
      any_fixed = any_fixed || part.is_fixed(k);
    if(VertexMaps::has_tolerance || any_fixed)
    {
      m_tolerance.assign(n, epsilon);
      for(std::size_t k = 0; k < n; ++k)
        if(part.is_fixed(k))
          m_tolerance[rank[k]] = 0;
    }
    // Zero for the fixed vertices, whose values are not read.
    if(VertexMaps::has_box_half_extents)
      m_extents.setZero(Eigen::Index(n), 3);
    if(VertexMaps::has_box_center)
      m_centre.setZero(Eigen::Index(n), 3);
    part.for_each_vertex([&](std::size_t k, const auto& v) {
      if(part.is_fixed(k))
        return;
      const std::size_t i = rank[k];
      if constexpr(VertexMaps::has_tolerance)
        m_tolerance[i] = tolerance_of(maps, v, epsilon);
      if constexpr(VertexMaps::has_box_half_extents)
        point(m_extents, i) = maps.given_box_half_extents(v);
      if constexpr(VertexMaps::has_box_center)
        point(m_centre, i) = maps.given_box_center(v);
    });
  }

  bool is_box() const { return m_box; }

  // Vertex v's tolerance, min(epsilon, its own), as given (NaN and all).
  template <typename VertexMaps, typename Key>
  static double tolerance_of(const VertexMaps& maps, const Key& v, double epsilon)
  {
    if constexpr(VertexMaps::has_tolerance)
      return (std::min)(maps.given_tolerance(v), epsilon);
    else
      return epsilon;
  }

  // The bound on the input points X0 (in the solver's order); the ball takes over the data read.
  Ball_bound ball(const Points& X0) &&
  {
    return m_tolerance.empty() ? Ball_bound(X0, m_epsilon) : Ball_bound(X0, Bound_sizes(std::move(m_tolerance)));
  }

  Box_bound box(const Points& X0) const
  {
    const auto half_extents = [&](std::size_t i) {
      const Eigen::Vector3d h = m_extents.rows() > 0 ? Eigen::Vector3d(point(m_extents, i)) : m_uniform_extents;
      return Eigen::Vector3d(h.cwiseMin(tolerance(i)));
    };
    const auto centre = [&](std::size_t i) {
      return Eigen::Vector3d(m_centre.rows() > 0 && tolerance(i) > 0 ? point(m_centre, i) : point(X0, i));
    };
    return Box_bound(X0, half_extents, centre);
  }

private:
  double tolerance(std::size_t i) const { return m_tolerance.empty() ? m_epsilon : m_tolerance[i]; }

  bool m_box = false;
  double m_epsilon = 0;
  std::vector<double> m_tolerance; // empty: epsilon for every vertex
  Eigen::Vector3d m_uniform_extents;
  Points m_extents, m_centre;      // empty: m_uniform_extents, the input points
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BOUND_PARAMETERS_H
