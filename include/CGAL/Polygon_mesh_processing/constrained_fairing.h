// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_H
#define CGAL_PMP_CONSTRAINED_FAIRING_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Active_set_newton.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Deviation_bounds.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input_check.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Projected_lbfgs.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Solver_report.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Vertex_order.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/assertions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

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

// Runs the method of `options` within `bound`.
template <typename Bound, typename SparseLinearSolver, typename Callback>
Solver_report fair(const Hinge_mesh& mesh, const Bound& bound, Bending_energy& energy, Constrained_fairing_method method,
                   const Solver_options& options, const SparseLinearSolver& solver, const Callback& callback, Points& X)
{
  if(method == Constrained_fairing_method::QUASI_NEWTON)
    return Projected_lbfgs<Bound>(bound, energy).run(X, options, callback);
  return Active_set_newton<Bound, SparseLinearSolver>(mesh, bound, energy, solver).run(X, options, callback);
}

// The stopping rule of each method when the user sets none: the quasi-Newton method's energy
// keeps decreasing in small, uneven steps, with plateaus of tens of iterations, long after the
// noise is gone, so it is judged over 50 iterations and against a smaller threshold.
inline Solver_options default_options(Constrained_fairing_method method)
{
  Solver_options options;
  if(method == Constrained_fairing_method::QUASI_NEWTON)
  {
    options.threshold = 1e-4;
    options.window = 50;
    options.max_iterations = 1000;
  }
  options.cauchy_steps_only = method == Constrained_fairing_method::PROJECTED_GRADIENT;
  return options;
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

The bound holds in double arithmetic with no tolerance: computed from the output and input
points as doubles, `squared_distance(p, p0) <= epsilon * epsilon` and
`sqrt(squared_distance(p, p0)) <= epsilon` (ball), or `|p.x() - p0.x()| <= epsilon` and
likewise for `y` and `z` (box).

The iterations stop when the energy decreased by less than `energy_decrease_threshold` per
iteration relatively, on average over the last 50 iterations (quasi-Newton method) or the last
three (the paper's methods), when no feasible direction decreases it, or after
`number_of_iterations` iterations.

The loops over vertices, triangles and hinges run in parallel when %CGAL is linked with TBB
(`CGAL_LINKED_WITH_TBB`); the result is bit-identical for any number of threads.

<b>Input.</b> The mesh is checked before anything else; a mesh that breaks this contract gives
`Constrained_fairing_status::INVALID_INPUT`, a message naming the defect and the first
vertex or face concerned (numbered from 0 in the order `vertices(tmesh)` and `faces(tmesh)`
list them, which for a mesh read from a file is the file's order), and `tmesh` untouched.
The checks, in the order they are made:
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
    \cgalParamDefault{`Deviation_bound::BALL`}
  \cgalParamNEnd
  \cgalParamNBegin{fairing_method}
    \cgalParamDescription{the optimization method}
    \cgalParamType{`CGAL::Polygon_mesh_processing::Constrained_fairing_method`}
    \cgalParamDefault{`Constrained_fairing_method::QUASI_NEWTON`}
  \cgalParamNEnd
  \cgalParamNBegin{energy_decrease_threshold}
    \cgalParamDescription{the stopping threshold on the relative energy decrease per
                          iteration (averaged over 50 iterations for `QUASI_NEWTON`, three for the
                          paper's methods); `0` runs all `number_of_iterations` iterations}
    \cgalParamType{double}
    \cgalParamDefault{`1e-4` for `QUASI_NEWTON`, `1e-3` for the paper's methods}
  \cgalParamNEnd
  \cgalParamNBegin{conjugate_gradient_iterations}
    \cgalParamDescription{the largest number of preconditioned conjugate gradient iterations
                          per Newton step (`ACTIVE_SET_NEWTON` only), at least 1 (fewer when the
                          residual fell by 100); the thin plate Hessian only models the energy's,
                          and one iteration lowered the energy fastest per second in our measurements}
    \cgalParamType{std::size_t}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{iteration_callback}
    \cgalParamDescription{called after each iteration with its number (from 1) and the energy
                          reached; returning `false` stops the run, and the mesh gets that
                          iterate}
    \cgalParamType{a callable `bool(std::size_t, double)`}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return a `Constrained_fairing_result`: the status, the iterations and energy evaluations, the
        energy before and after, the largest deviation reached, and on failure the reason.

\warning The computation is done in double precision, and so is the guarantee.
*/
template <typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Constrained_fairing_result constrained_fairing(TriangleMesh& tmesh, double epsilon,
                                               const NamedParameters& np = parameters::default_values())
{
  namespace CF = internal::Constrained_fairing;
  using parameters::choose_parameter;
  using parameters::get_parameter;

  using GT = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Point_3 = typename GT::Point_3;
  using Sparse_linear_solver =
    typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                 CF::Default_sparse_linear_solver>::type;

  auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tmesh));
  const Constrained_fairing_method method =
    choose_parameter(get_parameter(np, CF::fairing_method), Constrained_fairing_method::QUASI_NEWTON);
  CF::Solver_options options = CF::default_options(method);
  options.max_iterations = static_cast<std::size_t>(
    choose_parameter(get_parameter(np, internal_np::number_of_iterations), options.max_iterations));
  options.threshold = choose_parameter(get_parameter(np, CF::energy_decrease_threshold), options.threshold);
  options.cg_iterations = (std::max)(std::size_t(1), static_cast<std::size_t>(choose_parameter(
    get_parameter(np, CF::conjugate_gradient_iterations), options.cg_iterations)));
  const Deviation_bound shape = choose_parameter(get_parameter(np, CF::deviation_bound), Deviation_bound::BALL);
  const auto callback = choose_parameter(get_parameter(np, CF::iteration_callback), CF::Always_continue());
  const auto solver = choose_parameter<Sparse_linear_solver>(get_parameter(np, internal_np::sparse_linear_solver));
  CGAL_precondition(options.threshold >= 0);

  Constrained_fairing_result result;
  if(num_vertices(tmesh) == 0)
  {
    result.message = "the mesh is empty";
    return result;
  }

  // Vertices are numbered in the order `vertices(tmesh)` lists them.
  auto vertex_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tmesh);
  std::size_t n = 0;
  for(auto v : vertices(tmesh))
    put(vertex_index, v, n++);
  result.message = CF::connectivity_error(tmesh, vertex_index);
  if(result.message.empty())
    result.message = CF::size_error(tmesh);
  if(!result.message.empty())
    return result;

  CF::Points X0(static_cast<Eigen::Index>(n), 3);
  for(auto v : vertices(tmesh))
  {
    const Point_3& p = get(vpm, v);
    X0.row(static_cast<Eigen::Index>(get(vertex_index, v))) << CGAL::to_double(p.x()), CGAL::to_double(p.y()),
      CGAL::to_double(p.z());
  }
  result.message = CF::coordinates_error(X0);
  if(result.message.empty())
    result.message = CF::epsilon_error(epsilon);
  if(!result.message.empty())
    return result;

  // From here on, the vertices are stored in the Hilbert order of their input positions.
  {
    const std::vector<CF::Index> rank = CF::hilbert_rank(X0);
    CF::Points sorted(X0.rows(), 3);
    for(auto v : vertices(tmesh))
    {
      const std::size_t i = get(vertex_index, v);
      sorted.row(rank[i]) = X0.row(static_cast<Eigen::Index>(i));
      put(vertex_index, v, std::size_t(rank[i]));
    }
    X0.swap(sorted);
  }
  const CF::Hinge_mesh mesh(tmesh, vertex_index);
  CF::Bending_energy energy(mesh, X0);
  if(!energy.is_defined())
  {
    result.message = "all triangles of the mesh have zero area";
    return result;
  }
  result.initial_energy = result.final_energy = energy.value(X0);
  result.number_of_degenerate_edges = energy.number_of_degenerate_hinges();
  result.status = Constrained_fairing_status::ITERATION_LIMIT_REACHED;
  if(options.max_iterations == 0)
    return result;

  CF::Points X = X0;
  CF::Solver_report report;
  if(shape == Deviation_bound::BALL)
  {
    const CF::Ball_bound bound(X0, epsilon);
    report = CF::fair(mesh, bound, energy, method, options, solver, callback, X);
    result.max_deviation = bound.max_deviation(X);
  }
  else
  {
    const CF::Box_bound bound(X0, epsilon);
    report = CF::fair(mesh, bound, energy, method, options, solver, callback, X);
    result.max_deviation = bound.max_deviation(X);
  }
  result.status = report.status;
  result.message = report.message;
  result.number_of_iterations = report.iterations;
  result.number_of_cg_iterations = report.cg_iterations;
  result.number_of_energy_evaluations = report.energy_evaluations;
  if(!result)
  {
    result.max_deviation = 0;
    return result;
  }
  result.final_energy = report.final_energy;
  for(auto v : vertices(tmesh))
  {
    const auto i = static_cast<std::size_t>(get(vertex_index, v));
    put(vpm, v, Point_3(X(i, 0), X(i, 1), X(i, 2)));
  }
  return result;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_H
