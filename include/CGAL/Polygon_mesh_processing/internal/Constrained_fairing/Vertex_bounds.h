// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the named parameters ask of each vertex that takes part in the fairing, read and
// checked before anything is done, then turned into the solver's Ball_bound or Box_bound,
// which holds it from then on:
//  - its tolerance t_i = min(epsilon, vertex_tolerance_map(v)), or 0 for a fixed vertex;
//  - for the box, its half-extents min(t_i, H_i) per axis, H_i from vertex_box_half_extents_map
//    or box_half_extents (t_i alone without them), around vertex_box_center_map(v) or the
//    input position (always the input position for a vertex of tolerance 0, which so stays
//    where it is).
// epsilon thus caps every size, and a fixed vertex's coordinates come out bit-identical.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VERTEX_BOUNDS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VERTEX_BOUNDS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Points.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Vertex_bounds
{
public:
  // Reads the named parameters for the vertices of `part` (Fairing_part.h), storing vertex k
  // of the part at rank[k], its place in the solver's order. Returns the first defect
  // (Input_check.h) in the order of the part, none if every value is usable.
  template <typename Part, typename NamedParameters>
  Input_error read(const Part& part, const std::vector<Index>& rank, double epsilon, const NamedParameters& np)
  {
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    constexpr bool has_tolerance = !is_default_parameter<NamedParameters, vertex_tolerance_map_t>::value;
    constexpr bool has_extents = !is_default_parameter<NamedParameters, box_half_extents_t>::value;
    constexpr bool has_extents_map = !is_default_parameter<NamedParameters, vertex_box_half_extents_map_t>::value;
    constexpr bool has_centre_map = !is_default_parameter<NamedParameters, vertex_box_center_map_t>::value;
    constexpr bool box_parameters = has_extents || has_extents_map || has_centre_map;

    const bool box_asked =
      parameters::choose_parameter(get_parameter(np, deviation_bound), Deviation_bound::BALL) == Deviation_bound::BOX;
    if(box_parameters && !box_asked && !is_default_parameter<NamedParameters, deviation_bound_t>::value)
      return {Constrained_fairing_defect::BOX_WITH_BALL, "box half-extents or centres were given with the ball bound"};
    m_box = box_asked || box_parameters;
    m_epsilon = epsilon;

    const std::size_t n = part.size();
    bool any_fixed = false;
    for(std::size_t k = 0; k < n; ++k)
      any_fixed = any_fixed || part.is_fixed(k);
    if(has_tolerance || any_fixed)
      m_tolerance.assign(n, epsilon);
    m_uniform_extents = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    if constexpr(has_extents)
    {
      const std::array<double, 3> h = get_parameter(np, box_half_extents);
      for(int c = 0; c < 3; ++c)
        m_uniform_extents[c] = h[std::size_t(c)];
      if(!extents_error(m_uniform_extents).empty())
        return {Constrained_fairing_defect::INVALID_BOX_EXTENTS, "box_half_extents " + extents_error(m_uniform_extents)};
    }
    // Zero for the fixed vertices, whose values are not read.
    if constexpr(has_extents_map)
      m_extents.setZero(Eigen::Index(n), 3);
    if constexpr(has_centre_map)
      m_centre.setZero(Eigen::Index(n), 3);

    // The first bad value of a vertex that may move.
    Input_error error;
    part.for_each_vertex([&](std::size_t k, auto v) {
      if(error)
        return;
      const std::size_t i = rank[k];
      if(part.is_fixed(k))
      {
        m_tolerance[i] = 0;
        return;
      }
      const std::string vertex = "vertex " + std::to_string(part.number(k));
      if constexpr(has_tolerance)
      {
        const double t = CGAL::to_double(get(get_parameter(np, vertex_tolerance_map), v));
        if(!(t >= 0) || !std::isfinite(t))
          error = {Constrained_fairing_defect::INVALID_TOLERANCE,
                   vertex + " has a negative, NaN or infinite tolerance (" + std::to_string(t) + ")"};
        m_tolerance[i] = (std::min)(t, epsilon);
      }
      if constexpr(has_extents_map)
      {
        const auto& h = get(get_parameter(np, vertex_box_half_extents_map), v);
        for(int c = 0; c < 3; ++c)
          m_extents(Eigen::Index(i), c) = CGAL::to_double(h[c]);
        if(!error && !extents_error(point(m_extents, i)).empty())
          error = {Constrained_fairing_defect::INVALID_BOX_EXTENTS,
                   "the box half-extents of " + vertex + " " + extents_error(point(m_extents, i))};
      }
      if constexpr(has_centre_map)
      {
        const auto& c = get(get_parameter(np, vertex_box_center_map), v);
        point(m_centre, i) = Eigen::Vector3d(CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()));
        if(!error && !point(m_centre, i).allFinite())
          error = {Constrained_fairing_defect::INVALID_BOX_CENTER,
                   "the box centre of " + vertex + " has a NaN or infinite coordinate"};
      }
    });
    return error;
  }

  bool is_box() const { return m_box; }

  // The bound on the input points X0 (in the solver's order); the ball takes over the data read.
  Ball_bound ball(const Points& X0) &&
  {
    return m_tolerance.empty() ? Ball_bound(X0, m_epsilon) : Ball_bound(X0, Vertex_sizes(std::move(m_tolerance)));
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
  static std::string extents_error(const Eigen::Vector3d& h)
  {
    if(h.allFinite() && (h.array() >= 0).all())
      return std::string();
    return "must be finite and non-negative (" + std::to_string(h[0]) + ", " + std::to_string(h[1]) + ", " +
           std::to_string(h[2]) + ")";
  }

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

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VERTEX_BOUNDS_H
