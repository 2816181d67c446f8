// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One call of constrained_fairing(), in the phases of the method:
//  - check: the mesh, then every value of the input (coordinates, epsilon, weights, the
//    per-vertex bounds, the input positions in their boxes, the area) in the order of the
//    user's vertices, so that the first defect is reported and nothing else is done;
//  - order: the vertices of the part that moves, in the Hilbert order of their input positions
//    (Hilbert_order.h), the one numbering of everything that follows; the bounds are read
//    straight into it;
//  - build: the hinges, the objective (bending energy, barrier against slivers, fidelity);
//  - descend (Fairing_descent.h): from a smoothed start, then re-seeded descents around the
//    folds it left (Fold_repair.h), with one solver;
//  - report and write back: the result, the output maps, and the points that moved.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Bound_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_descent.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_part.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Value_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Mesh_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hilbert_order.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Fidelity_anchor.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solvers/Iteration_callback.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename TriangleMesh, typename VertexPointMap, typename SparseLinearSolver>
class Fairing_driver
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point_3 = typename boost::property_traits<VertexPointMap>::value_type;
  using Part = Fairing_part<TriangleMesh>;

public:
  Fairing_driver(TriangleMesh& tmesh, const VertexPointMap& vpm, const Fairing_settings& settings,
                 const SparseLinearSolver& solver)
    : m_tmesh(tmesh), m_vpm(vpm), m_settings(settings), m_solver(solver),
      m_vertex_index(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tmesh))
  {
    CGAL_precondition(settings.options.threshold >= 0);
  }

  // Fairs the faces of `region`, or the whole mesh if it is null, within `epsilon`; `np`
  // gives the per-vertex bounds (Bound_parameters.h), the fixed vertices and the output maps.
  template <typename FaceRange, typename NamedParameters, typename Callback>
  Constrained_fairing_result run(const FaceRange* region, double epsilon, const NamedParameters& np,
                                 const Callback& callback)
  {
    const std::optional<Part> part = check(region, epsilon, np);
    if(!part)
      return std::move(m_result);
    if(part->size() == 0) // an empty face range: nothing to do
    {
      m_result.status = Constrained_fairing_status::CONVERGED;
      return std::move(m_result);
    }
    Bound_parameters bounds = order(*part, epsilon, np);
    const Iteration_callback heard(callback);
    if(bounds.is_box())
      fair(*part, region != nullptr, std::move(bounds).box(m_X0), np, heard);
    else
      fair(*part, region != nullptr, std::move(bounds).ball(m_X0), np, heard);
    if(m_result)
      write_back(*part);
    return std::move(m_result);
  }

private:
  // Records the first defect found; true if there is none.
  bool accept(Input_error error)
  {
    m_result.defect = error.defect;
    m_result.message = std::move(error.message);
    return m_result.defect == Constrained_fairing_defect::NONE;
  }

  // The whole input contract: the mesh, its vertices numbered in messages in the order
  // vertices(tmesh) lists them, then the part that takes part and its values. Leaves the
  // part's input points in X0, in the part's order; nothing if there is a defect.
  template <typename FaceRange, typename NamedParameters>
  std::optional<Part> check(const FaceRange* region, double epsilon, const NamedParameters& np)
  {
    auto user_number = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m_tmesh);
    std::size_t count = 0;
    for(auto v : vertices(m_tmesh))
      put(user_number, v, count++);
    if(!accept(mesh_error(m_tmesh, user_number)))
      return std::nullopt;
    const auto is_constrained = parameters::choose_parameter(
      parameters::get_parameter(np, internal_np::vertex_is_constrained),
      CGAL::Static_boolean_property_map<vertex_descriptor, false>());
    std::optional<Part> part;
    if(region)
      part.emplace(*region, m_tmesh, user_number, is_constrained);
    else
      part.emplace(m_tmesh, is_constrained);
    if(part->size() > 0 && !accept(value_error(*part, epsilon, np)))
      return std::nullopt;
    return part;
  }

  template <typename NamedParameters>
  Input_error value_error(const Part& part, double epsilon, const NamedParameters& np)
  {
    m_X0.resize(static_cast<Eigen::Index>(part.size()), 3);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
      const Point_3& p = get(m_vpm, v);
      point(m_X0, k) = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    });
    return Constrained_fairing::value_error(part, m_X0, [&] { return part_triangles(part); }, epsilon, m_settings, np);
  }

  // The triangles of the part, its vertices numbered in the part's order.
  std::vector<std::array<Index, 3> > part_triangles(const Part& part) const
  {
    auto place = get(CGAL::dynamic_vertex_property_t<Index>(), m_tmesh);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) { put(place, v, static_cast<Index>(k)); });
    std::vector<std::array<Index, 3> > triangles;
    const auto add = [&](auto f) {
      const auto h = halfedge(f, m_tmesh);
      triangles.push_back({get(place, source(h, m_tmesh)), get(place, target(h, m_tmesh)),
                           get(place, target(next(h, m_tmesh), m_tmesh))});
    };
    if(part.triangles().empty())
      for(auto f : faces(m_tmesh))
        add(f);
    else
      for(auto f : part.triangles())
        add(f);
    return triangles;
  }

  // The input points, the moving vertices and the bounds in the solver's order.
  template <typename NamedParameters>
  Bound_parameters order(const Part& part, double epsilon, const NamedParameters& np)
  {
    const std::vector<Index> rank = hilbert_rank(m_X0);
    Bound_parameters bounds;
    bounds.read(part, rank, epsilon, np);
    Points X0(m_X0.rows(), 3);
    m_moving.assign(part.size(), false);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
      point(X0, rank[k]) = point(m_X0, k);
      put(m_vertex_index, v, std::size_t(rank[k]));
      m_moving[rank[k]] = !part.is_fixed(k);
    });
    m_X0.swap(X0);
    return bounds;
  }

  // Every step of the method, then the report.
  template <typename Bound, typename NamedParameters>
  void fair(const Part& part, bool is_region, const Bound& bound, const NamedParameters& np,
            const Iteration_callback& callback)
  {
    const Hinge_mesh mesh = build_hinges(part, is_region);
    Fairing_objective energy(mesh, m_X0, m_settings.sliver_barrier_weight);
    Points anchor;
    if(m_settings.is_accurate())
    {
      anchor = m_X0;
      Fidelity_anchor(mesh).apply(bound, anchor);
      energy.add_fidelity(m_settings.fidelity_weight, [&bound](std::size_t i) { return bound.size(i); }, anchor);
    }
    Fairing_descent<Bound, SparseLinearSolver>(mesh, bound, m_moving, m_settings, m_solver)
      .run(m_X0, energy, anchor, callback, m_X, m_result);
    if(m_result)
      report(bound, np, part, is_region);
  }

  Hinge_mesh build_hinges(const Part& part, bool is_region) const
  {
    if(!is_region)
      return Hinge_mesh(m_tmesh, m_vertex_index);
    // A hinge counts when one of its four vertices moves.
    return Hinge_mesh(m_tmesh, part.triangles(), part.size(), m_vertex_index, [&](const std::array<Index, 4>& v) {
      return m_moving[v[0]] || m_moving[v[1]] || m_moving[v[2]] || m_moving[v[3]];
    });
  }

  // The result's counts and the output maps, 0 and false for the vertices outside the part.
  template <typename Bound, typename NamedParameters>
  void report(const Bound& bound, const NamedParameters& np, const Part& part, bool is_region)
  {
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    count_bound(bound, m_moving, m_X, m_result);
    const auto is_at_bound = [&](std::size_t i) { return Constrained_fairing::is_at_bound(bound, m_moving, m_X, i); };
    if constexpr(!is_default_parameter<NamedParameters, vertex_deviation_map_t>::value)
    {
      const auto deviation_map = get_parameter(np, vertex_deviation_map);
      if(is_region)
        for(auto v : vertices(m_tmesh))
          put(deviation_map, v, 0);
      part.for_each_vertex([&](std::size_t, vertex_descriptor v) {
        put(deviation_map, v, bound.deviation(m_X, get(m_vertex_index, v)));
      });
    }
    if constexpr(!is_default_parameter<NamedParameters, vertex_at_bound_map_t>::value)
    {
      const auto at_bound_map = get_parameter(np, vertex_at_bound_map);
      if(is_region)
        for(auto v : vertices(m_tmesh))
          put(at_bound_map, v, false);
      part.for_each_vertex(
        [&](std::size_t, vertex_descriptor v) { put(at_bound_map, v, is_at_bound(get(m_vertex_index, v))); });
    }
  }

  // Only moved vertices are written: the others keep their coordinates exactly, even in an
  // exact kernel.
  void write_back(const Part& part)
  {
    part.for_each_vertex([&](std::size_t, vertex_descriptor v) {
      const std::size_t i = get(m_vertex_index, v);
      if(point(m_X, i) != point(m_X0, i))
        put(m_vpm, v, Point_3(m_X(i, 0), m_X(i, 1), m_X(i, 2)));
    });
  }

  TriangleMesh& m_tmesh;
  VertexPointMap m_vpm;
  const Fairing_settings& m_settings;
  const SparseLinearSolver& m_solver;
  Constrained_fairing_result m_result;
  // Each vertex's place in the solver's order, from the order phase on.
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type
    m_vertex_index;
  std::vector<bool> m_moving; // in the solver's order
  Points m_X0, m_X; // the input points (in the part's order while checking) and the current points
};


// One call on the faces of `region` (all of them if it is null) with `settings`, read from `np`
// or given by a front end; `np` gives the point map, the per-vertex maps, the callback and the
// linear solver.
template <typename TriangleMesh, typename FaceRange, typename NamedParameters>
Constrained_fairing_result run_fairing_driver(const FaceRange* region, TriangleMesh& tmesh, double epsilon,
                                              const Fairing_settings& settings, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Sparse_linear_solver =
    typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                 Default_sparse_linear_solver>::type;
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, tmesh));
  const auto solver = choose_parameter<Sparse_linear_solver>(get_parameter(np, internal_np::sparse_linear_solver));
  Fairing_driver<TriangleMesh, std::remove_const_t<decltype(vpm)>, Sparse_linear_solver> driver(tmesh, vpm, settings,
                                                                                                 solver);
  return driver.run(region, epsilon, np, choose_parameter(get_parameter(np, iteration_callback), Always_continue()));
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
