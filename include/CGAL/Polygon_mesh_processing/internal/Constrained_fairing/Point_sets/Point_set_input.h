// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A point set as the driver (Fairing_driver.h) fairs it, a model of its Input concept
// (Fairing_input.h): a range of points, read and written through a point map, with normals
// the user's or estimated (Point_normals.h). What differs from a mesh:
//  - its structure is each point's k nearest neighbours (Point_neighbours.h) and its tangent
//    fan (Tangent_fans.h), checked by Point_set_check.h; a point with no usable neighbourhood
//    stays where it is;
//  - it has no hinges: its bending energy is a term, the operator form of its fans' Laplacian
//    (Operator_bending.h); the fans' triangles serve the shared operators (the normals along
//    which the points move, the smoothed start), and no barrier, since no triangle is output;
//  - the accurate objective's anchor is CGAL's jet smoothing, within the bound;
//  - after the descent, the normals at the result are written to the normal map, if it is
//    writable, oriented as the input's.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_INPUT_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_INPUT_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Numbered_part.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Operator_bending.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/Vertex_maps.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_neighbours.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_set_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Tangent_fans.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/jet_smooth_point_set.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename PointRange, typename PointMap, typename NormalMap>
class Point_set_input
{
  using Point = typename boost::property_traits<PointMap>::value_type;
  using Vector = typename Kernel_traits<Point>::Kernel::Vector_3;

public:
  static constexpr bool bends_by_hinges = false;

  // `k` neighbours per point; `method` the settings', which must be the quasi-Newton method.
  Point_set_input(PointRange& points, PointMap point_map, NormalMap normal_map, std::size_t k,
                  Constrained_fairing_method method)
    : m_point_map(point_map), m_normal_map(normal_map), m_k(k), m_method(method)
  {
    for(auto it = points.begin(); it != points.end(); ++it)
      m_items.push_back(it);
  }

  // The points' and normals' values, their neighbours and fans.
  Input_error structure_error()
  {
    if(m_method != Constrained_fairing_method::QUASI_NEWTON)
      return method_needs_mesh_error();
    const std::size_t n = m_items.size();
    m_X.resize(Eigen::Index(n), 3);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Point& p = get(m_point_map, *m_items[i]);
      point(m_X, i) = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    std::optional<Points> normals;
    if constexpr(is_given_map<NormalMap>)
    {
      normals.emplace(m_X.rows(), 3);
      for(std::size_t i = 0; i < n; ++i)
      {
        const Vector& v = get(m_normal_map, *m_items[i]);
        point(*normals, i) = Eigen::Vector3d(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
      }
    }
    Point_set_structure structure = point_set_structure(m_X, normals, m_k);
    if(structure.error)
      return std::move(structure.error);
    m_N = std::move(structure.normals);
    m_isolated = std::move(structure.isolated);
    m_fans = std::move(structure.fans);
    return {};
  }

  // The isolated points stay, and those the user fixed.
  template <typename VertexMaps>
  Numbered_part part(const VertexMaps& maps) const
  {
    std::vector<bool> fixed = m_isolated;
    for(std::size_t k = 0; k < fixed.size(); ++k)
      fixed[k] = fixed[k] || maps.is_constrained(k);
    return Numbered_part(std::move(fixed));
  }

  Points input_points(const Numbered_part&) const { return m_X; }

  // The fans' triangles, for the area check.
  std::vector<std::array<Index, 3> > triangles(const Numbered_part&) const { return fan_triangles(); }

  void order(const Numbered_part&, const std::vector<Index>& rank)
  {
    m_rank = rank;
    std::vector<Tangent_fan> ordered(m_fans.size());
    for(std::size_t i = 0; i < m_fans.size(); ++i)
    {
      Tangent_fan& fan = ordered[rank[i]];
      fan = std::move(m_fans[i]);
      for(auto& t : fan.triangles)
        for(Index& v : t)
          v = rank[v];
      for(auto& entry : fan.weights)
        entry.first = rank[entry.first];
    }
    m_fans = std::move(ordered);
    Points normals(m_N.rows(), 3);
    for(std::size_t i = 0; i < rank.size(); ++i)
      point(normals, rank[i]) = point(m_N, i);
    m_N.swap(normals);
  }

  // The fans' triangles, no hinge.
  Hinge_mesh hinges(const Numbered_part& part, const std::vector<bool>&, const Points&, const Fairing_settings&) const
  {
    return Hinge_mesh(part.size(), fan_triangles(), {});
  }

  std::size_t number_of_feature_edges() const { return 0; }

  // Every point has a normal, its fan's.
  std::vector<bool> sliding_points(const Numbered_part&) const { return {}; }

  // No barrier: the fans are not output.
  double sliver_threshold(const Fairing_settings&) const { return 0; }

  // The bending energy of the closed fans' rows, each point's mass its own fan's: along the
  // normals where the points move along them, else of the whole vector (Operator_bending.h).
  void add_terms(Fairing_objective& objective, const Hinge_mesh&, const Points& X0, const Fairing_settings& settings)
  {
    const Eigen::Index n = X0.rows();
    std::size_t number_of_entries = 0, number_of_triangles = 0;
    for(const Tangent_fan& fan : m_fans)
      if(fan.is_closed())
        number_of_entries += fan.weights.size() + 1, number_of_triangles += fan.triangles.size();
    std::vector<Eigen::Triplet<double> > entries;
    std::vector<Mass_triangle> masses;
    entries.reserve(number_of_entries); // growing them would double the peak memory
    masses.reserve(number_of_triangles);
    for(std::size_t i = 0; i < m_fans.size(); ++i)
    {
      const Tangent_fan& fan = m_fans[i];
      if(!fan.is_closed())
        continue;
      double diagonal = 0;
      for(const auto& [j, w] : fan.weights)
      {
        entries.emplace_back(Eigen::Index(i), Eigen::Index(j), w);
        diagonal -= w;
      }
      entries.emplace_back(Eigen::Index(i), Eigen::Index(i), diagonal);
      for(const auto& t : fan.triangles)
        masses.push_back({t, Index(i)});
    }
    Operator_bending::Laplacian L(n, n);
    L.setFromTriplets(entries.begin(), entries.end());
    m_bending.emplace(std::move(L), settings.slides(settings.is_box()) ? Points() : m_N, std::move(masses), X0);
    objective.add_term(*m_bending);
  }

  // The accurate objective's anchor: CGAL's jet smoothing over the same neighbours, projected
  // into the bound.
  template <typename Bound>
  void denoise(const Hinge_mesh&, const Bound& bound, Points& X) const
  {
    using Kernel = Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_3> points;
    points.reserve(std::size_t(X.rows()));
    for(Eigen::Index i = 0; i < X.rows(); ++i)
      points.emplace_back(X(i, 0), X(i, 1), X(i, 2));
    jet_smooth_point_set<Parallel_if_available_tag>(points, unsigned(m_k));
    for(Eigen::Index i = 0; i < X.rows(); ++i)
      if(m_fans[std::size_t(i)].is_closed())
        X.row(i) << points[std::size_t(i)].x(), points[std::size_t(i)].y(), points[std::size_t(i)].z();
    bound.project(X);
  }

  // No repair: the normals at the result, for the normal map, and the isolated points' count.
  template <typename Bound>
  void repair(const Hinge_mesh& mesh, const Bound&, const std::vector<bool>&, const Points&, Points& X,
              Fairing_objective&, const Fairing_settings&, Constrained_fairing_result& result)
  {
    m_faired_normals = vertex_normals(mesh, X);
    result.number_of_isolated_points = std::size_t(std::count(m_isolated.begin(), m_isolated.end(), true));
  }

  template <typename VertexMaps>
  void clear_outputs(const VertexMaps&) const
  {}

  // The normals at the result, where the map is writable; a point with none keeps its own.
  void write_own_outputs() const
  {
    if constexpr(is_writable_map<NormalMap>)
      for(std::size_t k = 0; k < m_items.size(); ++k)
      {
        const auto n = point(m_faired_normals, m_rank[k]);
        if(n.squaredNorm() > 0)
          put(m_normal_map, *m_items[k], Vector(n.x(), n.y(), n.z()));
      }
  }

  void write(std::size_t k, double x, double y, double z) { put(m_point_map, *m_items[k], Point(x, y, z)); }

private:
  std::vector<std::array<Index, 3> > fan_triangles() const
  {
    std::vector<std::array<Index, 3> > triangles;
    for(const Tangent_fan& fan : m_fans)
      triangles.insert(triangles.end(), fan.triangles.begin(), fan.triangles.end());
    return triangles;
  }

  PointMap m_point_map;
  NormalMap m_normal_map;
  std::size_t m_k;
  Constrained_fairing_method m_method;
  std::vector<typename PointRange::iterator> m_items;
  Points m_X;               // the input points, in the user's order
  Points m_N;               // their unit normals, in the user's order, then the solver's
  std::vector<bool> m_isolated;
  std::vector<Tangent_fan> m_fans; // in the user's numbering, then the solver's
  std::vector<Index> m_rank;
  std::optional<Operator_bending> m_bending;
  Points m_faired_normals;  // in the solver's order
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_INPUT_H
