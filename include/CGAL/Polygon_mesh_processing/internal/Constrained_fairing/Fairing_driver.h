// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One call of constrained_fairing(), in the phases of the method:
//  - check: the mesh, then every value of the input in the order of the user's vertices, so
//    that the first defect is reported and nothing else is done;
//  - order: the vertices of the part that moves, in the Hilbert order of their input positions
//    (Vertex_order.h), the one numbering of everything that follows; the bounds are read
//    straight into it;
//  - build: the hinges, the objective (bending energy, barrier against slivers, fidelity);
//  - start, solve, repair folds: a descent from a smoothed start, then re-seeded descents
//    around the folds it left (Fold_repair.h), with one solver;
//  - report and write back: the result, the output maps, and the points that moved.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Active_set_newton.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bending_energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bilateral_normal_filter.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Fairing_part.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Fairing_settings.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Fold_repair.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Projected_lbfgs.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Smoothed_start.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solver_report.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Vertex_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Vertex_order.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstddef>
#include <optional>
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
  {}

  // Fairs the faces of `region`, or the whole mesh if it is null, within `epsilon`; `np`
  // gives the per-vertex bounds (Vertex_bounds.h), the fixed vertices and the output maps.
  template <typename FaceRange, typename NamedParameters, typename Callback>
  Constrained_fairing_result run(const FaceRange* region, double epsilon, const NamedParameters& np,
                                 const Callback& callback)
  {
    if(!check_mesh())
      return std::move(m_result);
    const auto is_constrained = parameters::choose_parameter(
      parameters::get_parameter(np, internal_np::vertex_is_constrained),
      CGAL::Static_boolean_property_map<vertex_descriptor, false>());
    const Part part = region ? Part(*region, m_tmesh, m_vertex_index, is_constrained) : Part(m_tmesh, is_constrained);
    if(part.size() == 0) // an empty face range: nothing to do
    {
      m_result.status = Constrained_fairing_status::CONVERGED;
      return std::move(m_result);
    }
    Vertex_bounds bounds;
    if(!order(part, epsilon, np, bounds))
      return std::move(m_result);
    const Iteration_callback heard(callback);
    if(bounds.is_box())
      fair(part, region != nullptr, std::move(bounds).box(m_X0), np, heard);
    else
      fair(part, region != nullptr, std::move(bounds).ball(m_X0), np, heard);
    if(m_result)
      write_back(part);
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

  // The whole mesh, its vertices numbered in messages in the order vertices(tmesh) lists them.
  bool check_mesh()
  {
    std::size_t count = 0;
    for(auto v : vertices(m_tmesh))
      put(m_vertex_index, v, count++);
    return accept(mesh_error(m_tmesh, m_vertex_index));
  }

  // The input points and the parameters checked in the part's order, then stored in the
  // solver's: X0, which vertices move, vertex_index and the bounds.
  template <typename NamedParameters>
  bool order(const Part& part, double epsilon, const NamedParameters& np, Vertex_bounds& bounds)
  {
    const std::size_t n = part.size();
    const auto number = [&part](std::size_t k) { return part.number(k); };
    Points X(static_cast<Eigen::Index>(n), 3);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
      const Point_3& p = get(m_vpm, v);
      point(X, k) = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    });
    if(!accept(coordinates_error(X, number)) || !accept(epsilon_error(epsilon)) ||
       !accept(fidelity_weight_error(m_settings.fidelity_weight)) ||
       !accept(sliver_barrier_weight_error(m_settings.sliver_barrier_weight)))
      return false;

    m_rank = hilbert_rank(X);
    if(!accept(bounds.read(part, m_rank, epsilon, np)))
      return false;
    m_X0.resize(X.rows(), 3);
    m_moving.assign(n, false);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
      point(m_X0, m_rank[k]) = point(X, k);
      put(m_vertex_index, v, std::size_t(m_rank[k]));
      m_moving[m_rank[k]] = !part.is_fixed(k);
    });
    return true;
  }

  // The remaining checks on the bound (the input inside it) and the triangles (an area), the
  // method, then the report.
  template <typename Bound, typename NamedParameters>
  void fair(const Part& part, bool is_region, const Bound& bound, const NamedParameters& np,
            const Iteration_callback& callback)
  {
    std::size_t outside = part.size();
    part.for_each_vertex([&](std::size_t k, vertex_descriptor) {
      if(outside == part.size() && !bound.contains(m_X0, m_rank[k]))
        outside = k;
    });
    m_rank = std::vector<Index>();
    if(!accept(outside_box_error(outside, part.size(), [&part](std::size_t k) { return part.number(k); })))
      return;
    if(!descend_within(part, is_region, bound, callback))
      return;
    report(bound, np, part, is_region);
  }

  // Every step of the method but the report, whatever the named parameters.
  template <typename Bound>
  bool descend_within(const Part& part, bool is_region, const Bound& bound, const Iteration_callback& callback)
  {
    const Hinge_mesh mesh = build_hinges(part, is_region);
    if(!accept(area_error(Bending_energy::is_defined(mesh, m_X0))))
      return false;
    Fairing_objective energy(mesh, m_X0, m_settings.sliver_barrier_weight);
    Points anchor;
    if(m_settings.accurate)
    {
      anchor = m_X0;
      Bilateral_normal_filter(mesh).apply(bound, anchor);
      energy.add_fidelity(m_settings.fidelity_weight, [&bound](std::size_t i) { return bound.size(i); }, anchor);
    }
    m_result.initial_energy = m_result.final_energy = energy.value(m_X0);
    m_result.initial_bending_energy = m_result.final_bending_energy = energy.bending_energy(m_X0);
    m_result.number_of_degenerate_edges = energy.number_of_degenerate_hinges();
    m_result.status = Constrained_fairing_status::ITERATION_LIMIT_REACHED;
    m_X = m_X0;
    if(m_settings.options.max_iterations > 0)
    {
      start(mesh, bound, energy, anchor);
      solve(mesh, bound, energy, callback);
      if(!m_result)
        return false;
      m_result.final_bending_energy = energy.bending_energy(m_X);
    }
    return true;
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

  // The smoothed start (the accurate objective's anchor is one), kept only if it lowers the
  // objective, so that the result never has a higher objective than the input.
  template <typename Bound>
  void start(const Hinge_mesh& mesh, const Bound& bound, Fairing_objective& energy, const Points& anchor)
  {
    if(m_settings.options.smoothing_steps == 0)
      return;
    if(m_settings.accurate)
      m_X = anchor;
    else
      smooth_start(mesh, bound, m_settings.options.smoothing_steps, m_X);
    if(!(energy.value(m_X) < m_result.initial_energy))
      m_X = m_X0;
  }

  // The descent, then fold repair with the same solver.
  template <typename Bound>
  void solve(const Hinge_mesh& mesh, const Bound& bound, Fairing_objective& energy, const Iteration_callback& callback)
  {
    std::optional<Projected_lbfgs<Bound> > quasi_newton;
    std::optional<Active_set_newton<Bound, SparseLinearSolver> > active_set;
    if(m_settings.method == Constrained_fairing_method::QUASI_NEWTON)
      quasi_newton.emplace(bound, energy);
    else
      active_set.emplace(mesh, bound, energy, m_solver);
    const auto descend = [&](const Solver_options& options, const Iteration_callback& heard, Points& X) {
      return quasi_newton ? quasi_newton->run(X, options, heard) : active_set->run(X, options, heard);
    };
    Solver_report path = descend(m_settings.options, callback, m_X);
    if(path.status != Constrained_fairing_status::LINEAR_SOLVER_FAILED)
    {
      const Fold_count folds = repair_folds(mesh, bound, m_moving, descend, m_settings.options, callback, m_X, path);
      m_result.number_of_folded_faces = folds.after;
      m_result.number_of_unfolded_faces = folds.before > folds.after ? folds.before - folds.after : 0;
      m_result.final_energy = path.final_energy;
    }
    m_result.status = path.status;
    m_result.message = path.message;
    m_result.number_of_iterations = path.iterations;
    m_result.number_of_cg_iterations = path.cg_iterations;
    m_result.number_of_energy_evaluations = path.energy_evaluations;
  }

  // The result's counts and the output maps, 0 and false for the vertices outside the part.
  template <typename Bound, typename NamedParameters>
  void report(const Bound& bound, const NamedParameters& np, const Part& part, bool is_region)
  {
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    const std::size_t n = part.size();
    m_result.max_deviation = bound.max_deviation(m_X);
    typename Bound::Face face;
    const auto is_at_bound = [&](std::size_t i) {
      return m_moving[i] && bound.size(i) > 0 && bound.is_on_boundary(m_X, i, face);
    };
    for(std::size_t i = 0; i < n; ++i)
    {
      m_result.number_of_vertices_at_bound += is_at_bound(i);
      m_result.number_of_fixed_vertices += !m_moving[i] || !(bound.size(i) > 0);
    }
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
  // Each vertex's place: in vertices(tmesh) while the mesh is checked, then in the solver's order.
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type
    m_vertex_index;
  std::vector<Index> m_rank;  // the solver's place of each vertex of the part, while checking
  std::vector<bool> m_moving; // in the solver's order
  Points m_X0, m_X;           // the input and the current points, in the solver's order
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FAIRING_DRIVER_H
