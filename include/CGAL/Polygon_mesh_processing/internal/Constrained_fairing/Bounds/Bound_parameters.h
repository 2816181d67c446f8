// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the named parameters ask of each vertex that takes part in the fairing, checked before
// anything is done, then read and turned into the solver's Ball_bound or Box_bound, which holds
// it from then on:
//  - its tolerance t_i = min(epsilon, vertex_tolerance_map(v)), or 0 for a fixed vertex;
//  - for the box, its half-extents min(t_i, H_i) per axis, H_i from vertex_box_half_extents_map
//    or box_half_extents (t_i alone without them), around vertex_box_center_map(v) or the
//    input position (always the input position for a vertex of tolerance 0, which so stays
//    where it is).
// epsilon thus caps every size, and a fixed vertex's coordinates come out bit-identical.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BOUND_PARAMETERS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BOUND_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

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

class Bound_parameters
{
public:
  // The first defect of the values that `np` gives the vertices of `part` (Fairing_part.h), in
  // the part's order: a box parameter with the ball, a bad tolerance, half-extent or centre, then
  // an input position X.row(k) outside its box. Nothing is stored.
  template <typename Part, typename NamedParameters>
  static Input_error check(const Part& part, const Points& X, double epsilon, const NamedParameters& np)
  {
    Bound_parameters bounds;
    if(Input_error error = bounds.read_shape(epsilon, np))
      return error;
    Input_error error;
    bounds.for_each_vertex(part, np, [&](std::size_t k, const Vertex_values& values) {
      if(!error)
        error = values.error(part.number(k));
    });
    if(error || !has_centre_map<NamedParameters>())
      return error;
    // Only a centre of the user's can leave the input position outside its box.
    std::size_t outside = part.size();
    bounds.for_each_vertex(part, np, [&](std::size_t k, const Vertex_values& values) {
      if(outside == part.size() && values.tolerance > 0 &&
         !is_in_box(X.row(Eigen::Index(k)).data(), values.centre.data(), values.half_extents().data()))
        outside = k;
    });
    return outside < part.size() ? outside_box_error(part.number(outside)) : Input_error();
  }

  // Reads what `np` asks of the vertices of `part`, which check() accepted, storing vertex k of
  // the part at rank[k], its place in the solver's order.
  template <typename Part, typename NamedParameters>
  void read(const Part& part, const std::vector<Index>& rank, double epsilon, const NamedParameters& np)
  {
    read_shape(epsilon, np);
    const std::size_t n = part.size();
    bool any_fixed = false;
    for(std::size_t k = 0; k < n; ++k)
      any_fixed = any_fixed || part.is_fixed(k);
    if(has_tolerance_map<NamedParameters>() || any_fixed)
    {
      m_tolerance.assign(n, epsilon);
      for(std::size_t k = 0; k < n; ++k)
        if(part.is_fixed(k))
          m_tolerance[rank[k]] = 0;
    }
    // Zero for the fixed vertices, whose values are not read.
    if(has_extents_map<NamedParameters>())
      m_extents.setZero(Eigen::Index(n), 3);
    if(has_centre_map<NamedParameters>())
      m_centre.setZero(Eigen::Index(n), 3);
    for_each_vertex(part, np, [&](std::size_t k, const Vertex_values& values) {
      const std::size_t i = rank[k];
      if(!m_tolerance.empty())
        m_tolerance[i] = values.tolerance;
      if(m_extents.rows() > 0)
        point(m_extents, i) = values.extents;
      if(m_centre.rows() > 0)
        point(m_centre, i) = values.centre;
    });
  }

  bool is_box() const { return m_box; }

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
  // Whether the user gave the named parameter of tag `Tag`.
  template <typename NamedParameters, typename Tag>
  static constexpr bool given()
  {
    return !parameters::is_default_parameter<NamedParameters, Tag>::value;
  }
  template <typename NamedParameters>
  static constexpr bool has_tolerance_map()
  {
    return given<NamedParameters, vertex_tolerance_map_t>();
  }
  template <typename NamedParameters>
  static constexpr bool has_extents_map()
  {
    return given<NamedParameters, vertex_box_half_extents_map_t>();
  }
  template <typename NamedParameters>
  static constexpr bool has_centre_map()
  {
    return given<NamedParameters, vertex_box_center_map_t>();
  }

  // What the named parameters give a vertex that may move, as given (NaN and all).
  struct Vertex_values
  {
    double tolerance;              // min(epsilon, its own)
    Eigen::Vector3d extents;       // its own or the uniform ones, before the tolerance caps them
    Eigen::Vector3d centre;        // its own; unread without a centre map
    bool own_tolerance, own_extents, own_centre;
    double given_tolerance;

    Eigen::Vector3d half_extents() const { return extents.cwiseMin(tolerance); }

    Input_error error(std::size_t number) const
    {
      if(own_tolerance && (!(given_tolerance >= 0) || !std::isfinite(given_tolerance)))
        return invalid_tolerance_error(number, given_tolerance);
      if(own_extents && !are_valid_extents(extents))
        return invalid_box_extents_error("the box half-extents of vertex " + std::to_string(number), extents[0],
                                         extents[1], extents[2]);
      if(own_centre && !centre.allFinite())
        return invalid_box_center_error(number);
      return {};
    }
  };

  static bool are_valid_extents(const Eigen::Vector3d& h) { return h.allFinite() && (h.array() >= 0).all(); }

  // The shape of the bound and the uniform half-extents.
  template <typename NamedParameters>
  Input_error read_shape(double epsilon, const NamedParameters& np)
  {
    using parameters::get_parameter;
    constexpr bool box_parameters = given<NamedParameters, box_half_extents_t>() ||
                                    has_extents_map<NamedParameters>() || has_centre_map<NamedParameters>();
    const bool box_asked =
      parameters::choose_parameter(get_parameter(np, deviation_bound), Deviation_bound::BALL) == Deviation_bound::BOX;
    if(box_parameters && !box_asked && given<NamedParameters, deviation_bound_t>())
      return box_with_ball_error();
    m_box = box_asked || box_parameters;
    m_epsilon = epsilon;
    m_uniform_extents = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    if constexpr(given<NamedParameters, box_half_extents_t>())
    {
      const std::array<double, 3> h = get_parameter(np, box_half_extents);
      m_uniform_extents = Eigen::Vector3d(h[0], h[1], h[2]);
      if(!are_valid_extents(m_uniform_extents))
        return invalid_box_extents_error("box_half_extents", h[0], h[1], h[2]);
    }
    return {};
  }

  // f(k, values) for each vertex k of the part that may move, in the part's order.
  template <typename Part, typename NamedParameters, typename F>
  void for_each_vertex(const Part& part, const NamedParameters& np, const F& f) const
  {
    using parameters::get_parameter;
    part.for_each_vertex([&](std::size_t k, auto v) {
      if(part.is_fixed(k))
        return;
      Vertex_values values{m_epsilon,
                           m_uniform_extents,
                           Eigen::Vector3d::Zero(),
                           has_tolerance_map<NamedParameters>(),
                           has_extents_map<NamedParameters>(),
                           has_centre_map<NamedParameters>(),
                           m_epsilon};
      if constexpr(has_tolerance_map<NamedParameters>())
      {
        values.given_tolerance = CGAL::to_double(get(get_parameter(np, vertex_tolerance_map), v));
        values.tolerance = (std::min)(values.given_tolerance, m_epsilon);
      }
      if constexpr(has_extents_map<NamedParameters>())
      {
        const auto& h = get(get_parameter(np, vertex_box_half_extents_map), v);
        values.extents = Eigen::Vector3d(CGAL::to_double(h[0]), CGAL::to_double(h[1]), CGAL::to_double(h[2]));
      }
      if constexpr(has_centre_map<NamedParameters>())
      {
        const auto& c = get(get_parameter(np, vertex_box_center_map), v);
        values.centre = Eigen::Vector3d(CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()));
      }
      f(k, values);
    });
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

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BOUND_PARAMETERS_H
