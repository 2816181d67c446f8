// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input contract's values, checked by the driver once its input's structure is accepted
// (Mesh_check.h, Interface_check.h) and before anything is computed, in the order of
// Constrained_fairing_defect, one function per defect: the coordinates, epsilon, the weights of
// the settings, the bound's parameters and each vertex's, the input positions in their boxes,
// and an area for the energy.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VALUE_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VALUE_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Bound_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The parts (Mesh_part.h, Numbered_part.h) give size(), number(k) (vertex k's number in
// messages), is_fixed(k), for_each_vertex(f), f(k, key) with the key of the per-vertex maps, and
// `detects_creases`, whether `feature_angle` applies.

template <typename Part>
Input_error coordinate_error(const Part& part, const Points& X0)
{
  for(std::size_t k = 0; k < part.size(); ++k)
    if(!point(X0, k).allFinite())
      return non_finite_coordinate_error(part.number(k));
  return {};
}

inline Input_error epsilon_error(double epsilon)
{
  return std::isfinite(epsilon) && epsilon > 0 ? Input_error() : invalid_epsilon_error(epsilon);
}

inline Input_error fidelity_weight_error(const Fairing_settings& settings)
{
  const double mu = settings.fidelity_weight;
  return std::isfinite(mu) && mu >= 0 ? Input_error() : invalid_fidelity_weight_error(mu);
}

inline Input_error sliver_barrier_weight_error(const Fairing_settings& settings)
{
  const double w = settings.sliver_barrier_weight;
  return std::isfinite(w) && w >= 0 ? Input_error() : invalid_sliver_barrier_weight_error(w);
}

// NaN fails both comparisons. Where the part's input has no creases to detect (a multi-label
// surface), any angle is rejected rather than ignored.
template <typename Part>
Input_error feature_angle_error(const Part&, const Fairing_settings& settings)
{
  if(!settings.feature_angle)
    return {};
  if(!Part::detects_creases)
    return feature_angle_without_creases_error();
  const double degrees = *settings.feature_angle;
  return degrees > 0 && degrees < 180 ? Input_error() : invalid_feature_angle_error(degrees);
}

inline bool are_valid_box_extents(const Eigen::Vector3d& h) { return h.allFinite() && (h.array() >= 0).all(); }

// A box parameter with the ball named.
inline Input_error bound_shape_error(const Fairing_settings& settings)
{
  return settings.has_box_parameter && settings.deviation_bound == Deviation_bound::BALL ? box_with_ball_error()
                                                                                           : Input_error();
}

inline Input_error box_half_extents_error(const Fairing_settings& settings)
{
  const std::array<double, 3> given = settings.uniform_box_half_extents();
  const Eigen::Vector3d h(given[0], given[1], given[2]);
  return !settings.box_half_extents || are_valid_box_extents(h)
           ? Input_error()
           : invalid_box_extents_error("box_half_extents", h[0], h[1], h[2]);
}

// The first vertex that may move with a bad tolerance, box half-extents or box centre, in that
// order for each vertex: three defects in one pass, so that the first vertex with any of them is
// the one reported.
template <typename Part, typename VertexMaps>
Input_error vertex_bound_error(const Part& part, const VertexMaps& maps)
{
  Input_error error;
  part.for_each_vertex([&](std::size_t k, const auto& v) {
    if(error || part.is_fixed(k))
      return;
    if constexpr(VertexMaps::has_tolerance)
    {
      const double t = maps.given_tolerance(v);
      if(!(t >= 0) || !std::isfinite(t))
        error = invalid_tolerance_error(part.number(k), t);
    }
    if constexpr(VertexMaps::has_box_half_extents)
    {
      const Eigen::Vector3d h = maps.given_box_half_extents(v);
      if(!error && !are_valid_box_extents(h))
        error = invalid_box_extents_error("the box half-extents of vertex " + std::to_string(part.number(k)), h[0],
                                          h[1], h[2]);
    }
    if constexpr(VertexMaps::has_box_center)
      if(!error && !maps.given_box_center(v).allFinite())
        error = invalid_box_center_error(part.number(k));
  });
  return error;
}

// The first vertex that may move whose input position X0.row(k) is outside its box: only a
// centre of the user's can leave it there.
template <typename Part, typename VertexMaps>
Input_error input_position_error(const Part& part, const Points& X0, double epsilon, const Fairing_settings& settings,
                                 const VertexMaps& maps)
{
  Input_error error;
  if constexpr(VertexMaps::has_box_center)
  {
    const std::array<double, 3> given = settings.uniform_box_half_extents();
    const Eigen::Vector3d uniform(given[0], given[1], given[2]);
    part.for_each_vertex([&](std::size_t k, const auto& v) {
      if(error || part.is_fixed(k))
        return;
      const double t = Bound_parameters::tolerance_of(maps, v, epsilon);
      Eigen::Vector3d h = uniform;
      if constexpr(VertexMaps::has_box_half_extents)
        h = maps.given_box_half_extents(v);
      const Eigen::Vector3d c = maps.given_box_center(v), half_extents = h.cwiseMin(t);
      if(t > 0 && !is_in_box(X0.row(Eigen::Index(k)).data(), c.data(), half_extents.data()))
        error = outside_box_error(part.number(k));
    });
  }
  return error;
}

// The first defect of the values for the vertices of `part`, whose input points are X0 in the
// part's order; `triangles()` gives the triangles on them, in the same numbering, made only
// when every other value is accepted.
template <typename Part, typename Triangles, typename VertexMaps>
Input_error value_error(const Part& part, const Points& X0, const Triangles& triangles, double epsilon,
                        const Fairing_settings& settings, const VertexMaps& maps)
{
  for(Input_error error : {coordinate_error(part, X0), epsilon_error(epsilon), fidelity_weight_error(settings),
                           sliver_barrier_weight_error(settings), feature_angle_error(part, settings),
                           bound_shape_error(settings),
                           box_half_extents_error(settings)})
    if(error)
      return error;
  if(Input_error error = vertex_bound_error(part, maps))
    return error;
  if(Input_error error = input_position_error(part, X0, epsilon, settings, maps))
    return error;
  if(!Bending_energy::is_defined(triangles(), X0))
    return no_area_error();
  return {};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_VALUE_CHECK_H
