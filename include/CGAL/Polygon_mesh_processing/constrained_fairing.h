// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_H
#define CGAL_PMP_CONSTRAINED_FAIRING_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Active_set_newton.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bilateral_normal_filter.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Fairing_objective.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Fold_repair.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Projected_lbfgs.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Smoothed_start.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solver_report.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Vertex_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Vertex_order.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/assertions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Always_continue
{
  bool operator()(std::size_t, double) const { return true; }
};

using Default_sparse_linear_solver =
  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >;

// The accurate objective's fidelity weight, chosen on the benchmark fairing_accuracy over its
// whole set of meshes and noise levels (the user manual gives the alternatives' figures). Its
// anchor is made by Bilateral_normal_filter.h.
constexpr double default_fidelity_weight = 1e4;

// The weight of the barrier against slivers (Sliver_barrier.h), per triangle: at 1, a needle of
// 1.5 degrees costs 0.92, about as much as a right-angle bend between two equilateral triangles
// (0.87). On the benchmark fairing_accuracy, weights 0.5, 1 and 2 gave the same distance to the
// truth, normals and energies; the smallest angle over the set was 1.7, 1.8 and 2.2 degrees
// (accurate objective) and 2.3, 2.6 and 2.7 (fairest).
constexpr double default_sliver_barrier_weight = 1;

// The rounds of fold repair at most.
constexpr std::size_t fold_repair_rounds = 3;

// Runs the method of `options` within `bound`.
template <typename Bound, typename SparseLinearSolver, typename Callback>
Solver_report fair(const Hinge_mesh& mesh, const Bound& bound, Fairing_objective& energy, Constrained_fairing_method method,
                   const Solver_options& options, const SparseLinearSolver& solver, const Callback& callback, Points& X)
{
  if(method == Constrained_fairing_method::QUASI_NEWTON)
    return Projected_lbfgs<Bound>(bound, energy).run(X, options, callback);
  return Active_set_newton<Bound, SparseLinearSolver>(mesh, bound, energy, solver).run(X, options, callback);
}

// The stopping rule of each method when the user sets none: the quasi-Newton method's energy
// keeps decreasing in small, uneven steps, with plateaus of tens of iterations, long after the
// noise is gone, so it is judged over 50 iterations and against a smaller threshold. On large
// meshes its decrease stays near that threshold for hundreds of iterations, so where it stops
// there depends on rounding; the threshold was chosen on the energy traces of
// benchmark/fairing_table1 so that the call stops near the lowest energy of 500 iterations at
// every size. It starts from a smoothed input (Smoothed_start.h); the paper's methods start
// from the input.
inline Solver_options default_options(Constrained_fairing_method method)
{
  Solver_options options;
  if(method == Constrained_fairing_method::QUASI_NEWTON)
  {
    options.threshold = 1.25e-4;
    options.window = 50;
    options.max_iterations = 1000;
    options.smoothing_steps = 16;
  }
  options.cauchy_steps_only = method == Constrained_fairing_method::PROJECTED_GRADIENT;
  return options;
}

// The part of `tmesh` that takes part in a call: its vertices (in the order `vertices(tmesh)`
// lists them), those of them that stay, the triangles whose hinges may count, and which
// hinges do. With no face range: the whole mesh, every vertex free and every hinge counted.
// With a face range R: a vertex moves when all its faces are in R; the triangles are R and its
// neighbours across an edge, and a hinge counts when one of its four vertices moves.
template <typename TriangleMesh>
class Fairing_part
{
public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  // The whole mesh: no list is stored, the vertices are those of `tmesh` in their order.
  template <typename IsConstrained>
  Fairing_part(const TriangleMesh& tmesh, const IsConstrained& is_constrained)
    : m_tmesh(tmesh), m_size(static_cast<std::size_t>(num_vertices(tmesh)))
  {
    m_fixed.reserve(m_size);
    for(auto v : vertices(tmesh))
      m_fixed.push_back(get(is_constrained, v));
  }

  // A face range; `vertex_index` numbers the vertices in the order of vertices(tmesh).
  template <typename FaceRange, typename VertexIndexMap, typename IsConstrained>
  Fairing_part(const FaceRange& region, const TriangleMesh& tmesh, const VertexIndexMap& vertex_index,
               const IsConstrained& is_constrained)
    : m_tmesh(tmesh)
  {
    auto in_region = get(CGAL::dynamic_face_property_t<bool>(), tmesh);
    auto in_part = get(CGAL::dynamic_face_property_t<bool>(), tmesh);
    for(auto f : faces(tmesh))
    {
      put(in_region, f, false);
      put(in_part, f, false);
    }
    for(auto f : region)
      put(in_region, f, true);
    for(auto f : region)
      for(auto h : halfedges_around_face(halfedge(f, tmesh), tmesh))
        for(auto g : {face(h, tmesh), face(opposite(h, tmesh), tmesh)})
          if(g != boost::graph_traits<TriangleMesh>::null_face() && !get(in_part, g))
          {
            put(in_part, g, true);
            m_triangles.push_back(g);
          }
    auto taken = get(CGAL::dynamic_vertex_property_t<bool>(), tmesh);
    for(auto v : vertices(tmesh))
      put(taken, v, false);
    for(auto f : m_triangles)
      for(auto v : vertices_around_face(halfedge(f, tmesh), tmesh))
        put(taken, v, true);
    for(auto v : vertices(tmesh))
    {
      if(!get(taken, v))
        continue;
      bool moves = !get(is_constrained, v);
      for(auto f : faces_around_target(halfedge(v, tmesh), tmesh))
        moves = moves && (f == boost::graph_traits<TriangleMesh>::null_face() || get(in_region, f));
      m_vertices.push_back(v);
      m_numbers.push_back(get(vertex_index, v));
      m_fixed.push_back(!moves);
    }
    m_size = m_vertices.size();
  }

  std::size_t size() const { return m_size; }
  // The triangles of a face range's part (unused for the whole mesh).
  const std::vector<face_descriptor>& triangles() const { return m_triangles; }
  bool is_fixed(std::size_t k) const { return m_fixed[k]; }
  // Vertex k's position in vertices(tmesh), which names it in messages.
  std::size_t number(std::size_t k) const { return m_numbers.empty() ? k : m_numbers[k]; }

  // f(k, v) for each vertex v, k from 0.
  template <typename F>
  void for_each_vertex(const F& f) const
  {
    std::size_t k = 0;
    if(m_vertices.empty())
      for(auto v : vertices(m_tmesh))
        f(k++, v);
    else
      for(auto v : m_vertices)
        f(k++, v);
  }

private:
  const TriangleMesh& m_tmesh;
  std::size_t m_size = 0;
  std::vector<vertex_descriptor> m_vertices; // empty for the whole mesh
  std::vector<std::size_t> m_numbers;        // empty for the whole mesh
  std::vector<bool> m_fixed;
  std::vector<face_descriptor> m_triangles;
};

template <typename TriangleMesh, typename FaceRange, typename NamedParameters>
Constrained_fairing_result constrained_fairing(const FaceRange* region, TriangleMesh& tmesh, double epsilon,
                                               const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

  using GT = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Point_3 = typename GT::Point_3;
  using Sparse_linear_solver =
    typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                 Default_sparse_linear_solver>::type;

  auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tmesh));
  const auto is_constrained = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                               CGAL::Static_boolean_property_map<vertex_descriptor, false>());
  const Constrained_fairing_method method =
    choose_parameter(get_parameter(np, fairing_method), Constrained_fairing_method::QUASI_NEWTON);
  Solver_options options = default_options(method);
  options.max_iterations = static_cast<std::size_t>(
    choose_parameter(get_parameter(np, internal_np::number_of_iterations), options.max_iterations));
  options.threshold = choose_parameter(get_parameter(np, energy_decrease_threshold), options.threshold);
  options.cg_iterations = (std::max)(std::size_t(1), static_cast<std::size_t>(choose_parameter(
    get_parameter(np, conjugate_gradient_iterations), options.cg_iterations)));
  options.smoothing_steps =
    static_cast<std::size_t>(choose_parameter(get_parameter(np, initial_smoothing_steps), options.smoothing_steps));
  const auto callback = choose_parameter(get_parameter(np, iteration_callback), Always_continue());
  const auto solver = choose_parameter<Sparse_linear_solver>(get_parameter(np, internal_np::sparse_linear_solver));
  CGAL_precondition(options.threshold >= 0);

  Constrained_fairing_result result;
  // The checks of Input_check.h, in order; the first defect found ends the call.
  const auto rejected = [&result](Input_error error) {
    result.defect = error.defect;
    result.message = std::move(error.message);
    return bool(result.defect != Constrained_fairing_defect::NONE);
  };

  // Messages number the vertices in the order `vertices(tmesh)` lists them.
  auto vertex_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tmesh);
  std::size_t count = 0;
  for(auto v : vertices(tmesh))
    put(vertex_index, v, count++);
  if(rejected(mesh_error(tmesh, vertex_index)))
    return result;

  const Fairing_part<TriangleMesh> part =
    region ? Fairing_part<TriangleMesh>(*region, tmesh, vertex_index, is_constrained)
           : Fairing_part<TriangleMesh>(tmesh, is_constrained);
  const std::size_t n = part.size();
  if(n == 0) // an empty face range: nothing to do
  {
    result.status = Constrained_fairing_status::CONVERGED;
    return result;
  }
  const auto number = [&part](std::size_t k) { return part.number(k); };
  Points X0(static_cast<Eigen::Index>(n), 3);
  part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
    const Point_3& p = get(vpm, v);
    point(X0, k) = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  });
  const double mu = choose_parameter(get_parameter(np, fidelity_weight), default_fidelity_weight);
  const double sliver_weight =
    choose_parameter(get_parameter(np, sliver_barrier_weight), default_sliver_barrier_weight);
  // A fidelity term of weight 0 is none: the call is then that of the fairest objective.
  const bool accurate = choose_parameter(get_parameter(np, fairing_objective), Constrained_fairing_objective::FAIREST) ==
                          Constrained_fairing_objective::ACCURATE &&
                        mu > 0;
  Vertex_bounds bounds;
  if(rejected(coordinates_error(X0, number)) || rejected(epsilon_error(epsilon)) ||
     rejected(fidelity_weight_error(mu)) || rejected(sliver_barrier_weight_error(sliver_weight)) ||
     rejected(bounds.read(part, epsilon, np)))
    return result;

  // From here on, the vertices are stored in the Hilbert order of their input positions, and
  // `vertex_index` maps each vertex of the part to its place in that order.
  std::vector<bool> moving(n);
  {
    const std::vector<Index> rank = hilbert_rank(X0);
    Points sorted(X0.rows(), 3);
    part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
      point(sorted, rank[k]) = point(X0, k);
      put(vertex_index, v, std::size_t(rank[k]));
      moving[rank[k]] = !part.is_fixed(k);
    });
    X0.swap(sorted);
    bounds.permute(rank);
  }
  result.number_of_fixed_vertices = static_cast<std::size_t>(std::count(moving.begin(), moving.end(), false));
  const Hinge_mesh mesh =
    region ? Hinge_mesh(tmesh, part.triangles(), n, vertex_index,
                        [&](const std::array<Index, 4>& v) {
                          return moving[v[0]] || moving[v[1]] || moving[v[2]] || moving[v[3]];
                        })
           : Hinge_mesh(tmesh, vertex_index);
  Fairing_objective energy(mesh, X0, sliver_weight);

  Points X = X0;
  Points anchor;
  const auto run = [&](const auto& bound) {
    // Vertex i in the Hilbert order, named as in messages.
    const auto sorted_number = [&](std::size_t i) {
      std::size_t name = 0;
      part.for_each_vertex([&](std::size_t k, vertex_descriptor v) {
        if(get(vertex_index, v) == i)
          name = part.number(k);
      });
      return name;
    };
    if(rejected(outside_box_error(bound.first_outside(X0), n, sorted_number)) || rejected(area_error(energy.is_defined())))
      return;
    if(accurate)
    {
      anchor = X0;
      Bilateral_normal_filter(mesh).apply(bound, anchor);
      energy.add_fidelity(mu, [&bounds](std::size_t i) { return bounds.largest_size(i); }, anchor);
    }
    result.initial_energy = result.final_energy = energy.value(X0);
    result.initial_bending_energy = result.final_bending_energy = energy.bending_energy(X0);
    result.number_of_degenerate_edges = energy.number_of_degenerate_hinges();
    result.status = Constrained_fairing_status::ITERATION_LIMIT_REACHED;
    if(options.max_iterations > 0)
    {
      // The smoothed start is kept only if it lowers the energy, so that the result never
      // has a higher energy than the input.
      if(options.smoothing_steps > 0)
      {
        if(accurate)
          X = anchor;
        else
          smooth_start(mesh, bound, options.smoothing_steps, X);
        if(!(energy.value(X) < result.initial_energy))
          X = X0;
      }
      const Solver_report report = fair(mesh, bound, energy, method, options, solver, callback, X);
      result.status = report.status;
      result.message = report.message;
      result.number_of_iterations = report.iterations;
      result.number_of_cg_iterations = report.cg_iterations;
      result.number_of_energy_evaluations = report.energy_evaluations;
      if(!result)
        return;
      result.final_energy = report.final_energy;

      // Fold repair (Fold_repair.h), on the triangles with a vertex that moves. Each round
      // re-seeds the folds and descends again, within the iterations left; it is kept if its
      // objective is not higher and it leaves fewer folds (or was cancelled). The callback
      // hears only the iterates of a round that are below the objective reached before it.
      const auto folds = [&](const Points& Y) {
        std::vector<Index> folded = folded_triangles(mesh, Y);
        folded.erase(std::remove_if(folded.begin(), folded.end(),
                                    [&](Index f) {
                                      const auto& t = mesh.triangles[f];
                                      return !moving[t[0]] && !moving[t[1]] && !moving[t[2]];
                                    }),
                     folded.end());
        return folded;
      };
      std::vector<Index> folded = folds(X);
      const std::size_t folded_at_first = folded.size();
      for(std::size_t round = 0; round < fold_repair_rounds && !folded.empty() &&
                                 result.status != Constrained_fairing_status::CANCELLED &&
                                 result.number_of_iterations < options.max_iterations;
          ++round)
      {
        Solver_options left_options = options; // the iterations left of number_of_iterations
        left_options.max_iterations = options.max_iterations - result.number_of_iterations;
        Points Y = X;
        reseed_folds(mesh, bound, folded, Y);
        const double before = result.final_energy;
        const std::size_t done = result.number_of_iterations;
        const auto below = [&](std::size_t iteration, double e) { return e > before || callback(done + iteration, e); };
        const Solver_report again = fair(mesh, bound, energy, method, left_options, solver, below, Y);
        result.number_of_iterations += again.iterations;
        result.number_of_cg_iterations += again.cg_iterations;
        result.number_of_energy_evaluations += again.energy_evaluations;
        if(again.status == Constrained_fairing_status::LINEAR_SOLVER_FAILED || !(again.final_energy <= before))
          break;
        std::vector<Index> left = folds(Y);
        if(left.size() >= folded.size() && again.status != Constrained_fairing_status::CANCELLED)
          break;
        X.swap(Y);
        folded.swap(left);
        result.final_energy = again.final_energy;
        result.status = again.status;
      }
      result.number_of_folded_faces = folded.size();
      result.number_of_unfolded_faces = folded_at_first - folded.size();
      result.final_bending_energy = energy.bending_energy(X);
    }
    result.max_deviation = bound.max_deviation(X);
    typename std::decay_t<decltype(bound)>::Face face;
    const auto is_at_bound = [&](std::size_t i) {
      return moving[i] && bounds.tolerance(i) > 0 && bound.is_on_boundary(X, i, face);
    };
    for(std::size_t i = 0; i < n; ++i)
      result.number_of_vertices_at_bound += is_at_bound(i);

    // The outputs, 0 and false for the vertices outside the part.
    if constexpr(!is_default_parameter<NamedParameters, vertex_deviation_map_t>::value)
    {
      const auto deviation_map = get_parameter(np, vertex_deviation_map);
      if(region)
        for(auto v : vertices(tmesh))
          put(deviation_map, v, 0);
      part.for_each_vertex(
        [&](std::size_t, vertex_descriptor v) { put(deviation_map, v, bound.deviation(X, get(vertex_index, v))); });
    }
    if constexpr(!is_default_parameter<NamedParameters, vertex_at_bound_map_t>::value)
    {
      const auto at_bound_map = get_parameter(np, vertex_at_bound_map);
      if(region)
        for(auto v : vertices(tmesh))
          put(at_bound_map, v, false);
      part.for_each_vertex([&](std::size_t, vertex_descriptor v) { put(at_bound_map, v, is_at_bound(get(vertex_index, v))); });
    }
  };
  if(bounds.is_box())
    run(bounds.box(X0));
  else
    run(bounds.ball(X0));
  if(!result)
    return result;

  // Only moved vertices are written: the others keep their coordinates exactly, even in an
  // exact kernel.
  part.for_each_vertex([&](std::size_t, vertex_descriptor v) {
    const std::size_t i = get(vertex_index, v);
    if(point(X, i) != point(X0, i))
      put(vpm, v, Point_3(X(i, 0), X(i, 1), X(i, 2)));
  });
  return result;
}

} // namespace Constrained_fairing
} // namespace internal

/*!
\ingroup PkgConstrainedFairingRef

\brief fairs a triangle mesh while keeping every vertex within `epsilon` of its input position.

Minimizes the discrete bending energy of Wardetzky et al. over all vertex positions `p` with
`|p - p0| <= epsilon` (`p0` the input position), the problem of K. Hildebrandt and
K. Polthier, "Constraint-based fairing of surface meshes", SGP 2007. The default method is a
projected quasi-Newton (L-BFGS) method that reaches a given energy several times sooner than the
paper's active set Newton method and its explicit projected gradient method, which remain
available through `fairing_method`.
Noise and terracing go; nothing moves farther than `epsilon`, so setting `epsilon` to the
accuracy of the data (a scanner's precision, the voxel size of an isosurface) keeps that
accuracy. More iterations can only lower the energy. The connectivity is not changed; border
vertices move like the others, and border edges do not contribute to the energy.

<b>Slivers.</b> A hinge of the bending energy costs less the shorter its edge and the flatter
its triangles, so the energy alone ends with needles and caps of angles near 0 degrees. A
barrier is added to it: with `q = 4 sqrt(3) A / (l1^2 + l2^2 + l3^2)` a triangle's quality (1
when equilateral, `A` its area, `l` its edges) and `q0` about that of a needle with a 3 degree
angle, each triangle with `q < q0` adds `w (q0 / (q + q0 / 100) - 1)^2`, `w` the
`sliver_barrier_weight`. Better triangles are left alone, so that the shape and the bending
energy reached do not change; triangles degenerate in the input are left out, as in the energy.
`sliver_barrier_weight(0)` minimizes the paper's energy alone.

<b>Tolerances.</b> `epsilon` is the tolerance of every vertex and caps all the others:
- `vertex_tolerance_map` gives each vertex its own tolerance `t(v)`, and the vertex then stays
  within `min(epsilon, t(v))` (a scanner's accuracy varies with range and incidence angle). A
  tolerance of `0` pins the vertex.
- `vertex_is_constrained_map` fixes vertices: they do not move at all (their coordinates are
  not even written), and the hinges around them still count in the energy.
- The box bound (`deviation_bound(Deviation_bound::BOX)`, or any of the box parameters below)
  keeps each coordinate within `min(epsilon, t(v))` of its input value, or within the box's own
  half-extents along x, y and z (`box_half_extents` for all vertices, `vertex_box_half_extents_map`
  per vertex), each also capped by `min(epsilon, t(v))`. The box is centred at the input
  position, or at `vertex_box_center_map(v)`: the voxel cell of a vertex extracted from a volume,
  which may sit anywhere in it. The input position must lie in its box. The largest move is then
  the box's diagonal, not `epsilon`.

The bound holds in double arithmetic with no tolerance: computed from the output and input
points as doubles, with `r` the vertex's radius, `squared_distance(p, p0) <= r * r` and
`sqrt(squared_distance(p, p0)) <= r` (ball), or `|p.x() - c.x()| <= h_x` and likewise for `y`
and `z` (box, `c` its centre and `h` its half-extents).

The iterations stop when the energy decreased by less than `energy_decrease_threshold` per
iteration relatively, on average over the last 50 iterations (quasi-Newton method) or the last
three (the paper's methods), when no feasible direction decreases it, or after
`number_of_iterations` iterations.

The loops over vertices, triangles and hinges run in parallel when %CGAL is linked with TBB
(`CGAL_LINKED_WITH_TBB`); the result is bit-identical for any number of threads.

<b>Input.</b> The mesh is checked before anything else; a mesh that breaks this contract gives
`Constrained_fairing_status::INVALID_INPUT`, the defect's kind (a
`Constrained_fairing_defect`, in the result's `defect`), a message naming it and the first
vertex or face concerned (numbered from 0 in the order `vertices(tmesh)` and `faces(tmesh)`
list them, which for a mesh read from a file is the file's order), and `tmesh` untouched.
The checks, in the order they are made (the order of `Constrained_fairing_defect`):
- no vertex, or no face;
- broken halfedge links (`next()`, `prev()`, `opposite()`, `target()` and `face()` disagree);
- a face that is not a triangle;
- a non-manifold edge: more than two faces on an edge, or two faces sharing two vertices
  through two different edges;
- two neighbouring faces oriented inconsistently (both run through their shared vertices in
  the same direction): the dihedral angles of the energy need a consistent orientation;
- a non-manifold vertex, whose faces form more than one fan;
- more than 2^32 - 1 vertices or 1,431,655,765 faces;
- a NaN or infinite coordinate;
- `epsilon` negative, zero, NaN or infinite;
- `fidelity_weight` negative, NaN or infinite;
- `sliver_barrier_weight` negative, NaN or infinite;
- box parameters with `deviation_bound(Deviation_bound::BALL)`;
- `box_half_extents` negative, NaN or infinite;
- for each vertex that may move, in order: its tolerance, its box half-extents negative, NaN or
  infinite, or its box centre with a NaN or infinite coordinate;
- an input position outside its box;
- all triangles of zero area.

Isolated vertices are allowed and do not move. Degenerate triangles are allowed: the hinges
(interior edges with their two triangles) that have a triangle of (nearly) zero area in the
input have no dihedral angle and are left out of the energy; their vertices are faired by
their other hinges, which in practice opens the degenerate triangles. The areas and normals of
the other triangles are regularized at a scale of 1e-9 of the mean triangle area, which keeps
the energy finite if a triangle degenerates during the iterations; this changes nothing (in
double) on triangles larger than a tenth of the mean. No NaN or infinity can reach the mesh.

<b>All or nothing.</b> On `INVALID_INPUT` and `LINEAR_SOLVER_FAILED`, `tmesh` is left
bit-identical. An exception thrown during the call (`std::bad_alloc`, or an exception from
the callback or the linear solver) propagates, and `tmesh` is left bit-identical too, as
long as `put()` on the vertex point map does not throw. A run stopped by the callback
(`CANCELLED`) writes the last iterate, which is within the bound like every iterate.

\pre `energy_decrease_threshold >= 0` (in builds without preconditions, a negative or NaN
     threshold runs all `number_of_iterations` iterations)

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tmesh a triangle mesh, manifold and consistently oriented, possibly with borders
\param epsilon the largest distance a vertex may move, in the mesh's units
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones
          listed below; the parameters not in %CGAL are in the namespace
          `CGAL::Polygon_mesh_processing::constrained_fairing_parameters`

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
    \cgalParamType{a class model of `ReadWritePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of iterations; `0` leaves the mesh untouched. An
                          iteration is one accepted step of the quasi-Newton method (usually one
                          evaluation of the energy and its gradient), or a Cauchy step followed by
                          a Newton step (`ACTIVE_SET_NEWTON`), or a Cauchy step (`PROJECTED_GRADIENT`)}
    \cgalParamType{unsigned int}
    \cgalParamDefault{`1000` for `QUASI_NEWTON`, `200` for the paper's methods}
  \cgalParamNEnd
  \cgalParamNBegin{sparse_linear_solver}
    \cgalParamDescription{the solver that factorizes the Hessian approximation once and then
                          solves with it (`ACTIVE_SET_NEWTON` only; the other methods solve no
                          linear system)}
    \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
    \cgalParamDefault{`CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::%EigenType> >`}
    \cgalParamExtra{The solves dominate the Newton method's time on large meshes, where
                    `Eigen::CholmodSupernodalLLT` (Eigen's `CholmodSupport`, with an optimized
                    BLAS) is faster.}
  \cgalParamNEnd
  \cgalParamNBegin{deviation_bound}
    \cgalParamDescription{the shape of the set each vertex stays in: the ball of radius
                          `epsilon`, or the paper's box of side `2 epsilon`}
    \cgalParamType{`CGAL::Polygon_mesh_processing::Deviation_bound`}
    \cgalParamDefault{`Deviation_bound::BOX` if a box parameter is given, `Deviation_bound::BALL` otherwise}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_tolerance_map}
    \cgalParamDescription{each vertex's own tolerance (radius of its ball, half-side of its box),
                          capped by `epsilon`; `0` pins the vertex}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a
                   number type as value type}
    \cgalParamDefault{`epsilon` for every vertex}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{the vertices that must not move}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `bool`
                   as value type}
    \cgalParamDefault{no vertex is constrained}
  \cgalParamNEnd
  \cgalParamNBegin{box_half_extents}
    \cgalParamDescription{the half-extents along x, y and z of every vertex's box (a voxel's half
                          size), each capped by the vertex's tolerance; selects the box bound}
    \cgalParamType{`std::array<double, 3>`}
    \cgalParamDefault{the vertex's tolerance along each axis}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_box_half_extents_map}
    \cgalParamDescription{each vertex's box half-extents along x, y and z, each capped by the
                          vertex's tolerance; selects the box bound}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a
                   value type `h` with `h[0]`, `h[1]`, `h[2]` numbers (`std::array<double, 3>`,
                   a %CGAL `Vector_3`)}
    \cgalParamDefault{`box_half_extents`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_box_center_map}
    \cgalParamDescription{each vertex's box centre (ignored for a vertex of tolerance `0`, which
                          stays where it is); selects the box bound}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{the vertex's input position}
  \cgalParamNEnd
  \cgalParamNBegin{fairing_method}
    \cgalParamDescription{the optimization method}
    \cgalParamType{`CGAL::Polygon_mesh_processing::Constrained_fairing_method`}
    \cgalParamDefault{`Constrained_fairing_method::QUASI_NEWTON`}
  \cgalParamNEnd
  \cgalParamNBegin{fairing_objective}
    \cgalParamDescription{what is minimized inside the bound: the bending energy alone, or with a
                          fidelity term towards a denoised input, which brings the result closer to
                          the true surface of a noisy scan and keeps more of its detail (see the
                          user manual for the measurements)}
    \cgalParamType{`CGAL::Polygon_mesh_processing::Constrained_fairing_objective`}
    \cgalParamDefault{`Constrained_fairing_objective::FAIREST`}
  \cgalParamNEnd
  \cgalParamNBegin{fidelity_weight}
    \cgalParamDescription{the weight `mu` of the fidelity term of
                          `Constrained_fairing_objective::ACCURATE` (ignored otherwise): the term is
                          `mu` when every vertex is its tolerance away from its denoised position;
                          larger values keep the result nearer the denoised input, smaller ones
                          let it fairer; `0` is the fairest objective}
    \cgalParamType{double, finite and non-negative}
    \cgalParamDefault{`10000`}
  \cgalParamNEnd
  \cgalParamNBegin{sliver_barrier_weight}
    \cgalParamDescription{the weight `w` of the barrier against slivers (see above): each
                          triangle that is a needle of angle 1.5 degrees adds about `w`, and a
                          triangle with no angle below 3 degrees nothing; `0` leaves the
                          slivers that the energy alone makes}
    \cgalParamType{double, finite and non-negative}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{energy_decrease_threshold}
    \cgalParamDescription{the stopping threshold on the relative energy decrease per
                          iteration (averaged over 50 iterations for `QUASI_NEWTON`, three for the
                          paper's methods); `0` runs all `number_of_iterations` iterations}
    \cgalParamType{double}
    \cgalParamDefault{`1.25e-4` for `QUASI_NEWTON`, `1e-3` for the paper's methods}
  \cgalParamNEnd
  \cgalParamNBegin{conjugate_gradient_iterations}
    \cgalParamDescription{the largest number of preconditioned conjugate gradient iterations
                          per Newton step (`ACTIVE_SET_NEWTON` only), at least 1 (fewer when the
                          residual fell by 100); the thin plate Hessian only models the energy's,
                          and one iteration lowered the energy fastest per second in our measurements}
    \cgalParamType{std::size_t}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{initial_smoothing_steps}
    \cgalParamDescription{the steps of Taubin's non-shrinking smoothing (each vertex moved
                          towards, then away from the mean of its neighbours, and back into its
                          bound) that make the starting point, kept if they lower the energy; `0`
                          starts from the input. With `Constrained_fairing_objective::ACCURATE`,
                          any other value starts from the objective's denoised input instead.
                          The energy is not convex: on terraced input
                          (surface nets on thick slices) descent from the input stalls in the
                          terraces, and on noisy scans the smoothed start also leads to lower
                          minima}
    \cgalParamType{std::size_t}
    \cgalParamDefault{`16` for `QUASI_NEWTON`, `0` for the paper's methods}
  \cgalParamNEnd
  \cgalParamNBegin{iteration_callback}
    \cgalParamDescription{called after each iteration with its number (from 1) and the energy
                          reached; returning `false` stops the run, and the mesh gets that
                          iterate}
    \cgalParamType{a callable `bool(std::size_t, double)`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_deviation_map}
    \cgalParamDescription{receives each vertex's distance to its input position (`0` for the
                          vertices that take no part); written when the call succeeds}
    \cgalParamType{a class model of `WritablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a
                   floating point type as value type}
    \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_at_bound_map}
    \cgalParamDescription{receives whether each vertex that could move ended on the boundary of
                          its ball or box (`false` for fixed vertices); written when the call
                          succeeds}
    \cgalParamType{a class model of `WritablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `bool`
                   as value type}
    \cgalParamDefault{unused}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return a `Constrained_fairing_result`: the status, the iterations and energy evaluations, the
        energy before and after, the largest deviation reached, the vertices at their bound and
        the fixed ones, and on failure the reason.

\warning The computation is done in double precision, and so is the guarantee.
*/
template <typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Constrained_fairing_result constrained_fairing(TriangleMesh& tmesh, double epsilon,
                                               const NamedParameters& np = parameters::default_values())
{
  using Faces = std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>;
  return internal::Constrained_fairing::constrained_fairing(static_cast<const Faces*>(nullptr), tmesh, epsilon, np);
}

/*!
\ingroup PkgConstrainedFairingRef

\brief fairs the part of a triangle mesh made of the faces `face_range`, everything else
staying bit-identical.

As `constrained_fairing(tmesh, epsilon, np)`, with the same named parameters, but only the
vertices whose faces all lie in `face_range` move: the vertices on the border of the region
stay, and so does every vertex outside it. The energy is the sum over the hinges that touch a
moving vertex (as an edge end or an opposite vertex), so that the result meets the rest of the
mesh smoothly. Calling it with `faces(tmesh)` is the same as fairing the whole mesh; an empty
range changes nothing and returns `CONVERGED`. The whole
mesh is checked as for the other overload; vertices are numbered in messages as there.

\tparam FaceRange a model of `ConstRange` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
        as value type
\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param face_range the faces of the region, each listed once
\param tmesh a triangle mesh, manifold and consistently oriented, possibly with borders
\param epsilon the largest distance a vertex may move, in the mesh's units
\param np the named parameters of `constrained_fairing(tmesh, epsilon, np)`

\return a `Constrained_fairing_result`, whose energies are those of the hinges that count and
        whose fixed vertices include the region's border and its neighbours.
*/
template <typename FaceRange, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Constrained_fairing_result constrained_fairing(const FaceRange& face_range, TriangleMesh& tmesh, double epsilon,
                                               const NamedParameters& np = parameters::default_values())
{
  return internal::Constrained_fairing::constrained_fairing(&face_range, tmesh, epsilon, np);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_H
