// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one place where the named parameters of the public functions are read: into the plain
// settings (Fairing_settings.h, through the table of Named_settings.h), the per-vertex maps
// (Vertex_maps.h), the feature edges, the callback and the linear solver, which is all the
// drivers below them see.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_READ_NAMED_PARAMETERS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_READ_NAMED_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Named_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Vertex_maps.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/SparseCholesky>

#include <array>
#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

using Default_sparse_linear_solver =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;

// Whether `np` gives the parameter of tag `Tag`.
template <typename NamedParameters, typename Tag>
constexpr bool is_given_parameter = !parameters::is_default_parameter<NamedParameters, Tag>::value;

// The per-vertex maps that `np` gives.
template <typename NamedParameters>
auto read_vertex_maps(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto tolerance = choose_parameter(get_parameter(np, vertex_tolerance_map), No_map());
  const auto is_constrained =
    choose_parameter(get_parameter(np, internal_np::vertex_is_constrained), No_map());
  const auto extents = choose_parameter(get_parameter(np, vertex_box_half_extents_map), No_map());
  const auto centre = choose_parameter(get_parameter(np, vertex_box_center_map), No_map());
  const auto deviation = choose_parameter(get_parameter(np, vertex_deviation_map), No_map());
  const auto at_bound = choose_parameter(get_parameter(np, vertex_at_bound_map), No_map());
  return Vertex_maps<std::decay_t<decltype(tolerance)>, std::decay_t<decltype(is_constrained)>,
                     std::decay_t<decltype(extents)>, std::decay_t<decltype(centre)>,
                     std::decay_t<decltype(deviation)>, std::decay_t<decltype(at_bound)> >{
    tolerance, is_constrained, extents, centre, deviation, at_bound};
}

// The map of the edges to keep as creases that `np` gives (`edge_is_constrained_map`), or
// No_map.
template <typename NamedParameters>
auto read_feature_edge_map(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::edge_is_constrained), No_map());
}

// The settings that `np` gives, each one it does not give at its default.
template <typename NamedParameters>
Fairing_settings read_fairing_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Fairing_settings settings = choose_parameter(
    get_parameter(np, fairing_settings),
    Fairing_settings(choose_parameter(get_parameter(np, fairing_method), Constrained_fairing_method::QUASI_NEWTON)));
  for_each_named_setting(settings, [&np](const char*, const char*, auto tag, auto& field) {
    field = static_cast<std::decay_t<decltype(field)> >(choose_parameter(get_parameter(np, tag), field));
  });
  if constexpr(is_given_parameter<NamedParameters, deviation_bound_t>)
    settings.deviation_bound = get_parameter(np, deviation_bound);
  if constexpr(is_given_parameter<NamedParameters, box_half_extents_t>)
    settings.box_half_extents = std::array<double, 3>(get_parameter(np, box_half_extents));
  if constexpr(is_given_parameter<NamedParameters, number_of_neighbors_t>)
    settings.number_of_neighbors = std::size_t(get_parameter(np, number_of_neighbors));
  settings.has_box_parameter = settings.box_half_extents.has_value() ||
                               is_given_parameter<NamedParameters, vertex_box_half_extents_map_t> ||
                               is_given_parameter<NamedParameters, vertex_box_center_map_t>;
  return settings;
}

// The callback that `np` gives, or one that always continues.
template <typename NamedParameters>
auto read_iteration_callback(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, iteration_callback), Always_continue());
}

template <typename NamedParameters>
using Sparse_linear_solver_of =
  typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                               Default_sparse_linear_solver>::type;

// The linear solver that `np` gives, or the default one.
template <typename NamedParameters>
Sparse_linear_solver_of<NamedParameters> read_sparse_linear_solver(const NamedParameters& np)
{
  return parameters::choose_parameter<Sparse_linear_solver_of<NamedParameters> >(
    parameters::get_parameter(np, internal_np::sparse_linear_solver));
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_READ_NAMED_PARAMETERS_H
