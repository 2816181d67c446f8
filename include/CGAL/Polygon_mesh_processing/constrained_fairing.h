// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_H
#define CGAL_PMP_CONSTRAINED_FAIRING_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Driver/Fairing_driver.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Triangle_meshes/Mesh_input.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parameters/read_named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Both overloads: every named parameter read once, here; the driver does the rest on the faces
// of `region`, or on the whole mesh if it is null.
template <typename TriangleMesh, typename FaceRange, typename NamedParameters>
Constrained_fairing_result constrained_fairing(const FaceRange* region, TriangleMesh& tmesh, double epsilon,
                                               const NamedParameters& np)
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_property_map(CGAL::vertex_point, tmesh));
  const auto feature_edges = read_feature_edge_map(np);
  Mesh_input<TriangleMesh, std::remove_const_t<decltype(vpm)>, FaceRange, std::decay_t<decltype(feature_edges)> > input(
    tmesh, vpm, region, feature_edges);
  const auto callback = read_iteration_callback(np);
  return run_fairing_driver(input, epsilon, read_fairing_settings(np), read_vertex_maps(np),
                            Iteration_callback(callback), read_sparse_linear_solver(np));
}

} // namespace Constrained_fairing
} // namespace internal

/*!
\ingroup PkgConstrainedFairingRef

\brief fairs a triangle mesh while keeping every vertex within `epsilon` of its input position.

Minimizes the discrete bending energy of Wardetzky et al. over vertex positions `p` with
`|p - p0| <= epsilon` (`p0` the input position), the problem of K. Hildebrandt and
K. Polthier, "Constraint-based fairing of surface meshes", SGP 2007; by default over the
positions along the normals of a smoothed start only (see "Normal offsets" below). The default
method is a projected quasi-Newton (L-BFGS) method that, on the paper's problem
(`tangential_motion(true)`), reaches the lowest energy of 500 iterations of the paper's active
set Newton method and its explicit projected gradient method 57 to 145 times sooner in our
measurements (see the user manual); they remain available through `fairing_method`.
Noise and terracing go; nothing moves farther than `epsilon`, so setting `epsilon` to the
accuracy of the data (a scanner's precision, the voxel size of an isosurface) keeps that
accuracy. More iterations can only lower the energy. The connectivity is not changed; border
vertices move like the others, and border edges do not contribute to the energy.

<b>Normal offsets.</b> With the default method, the ball bound and the fairest objective, each
vertex moves only along
one line, the normal of the smoothed start at that vertex, within its ball: the energy is
minimized over these offsets, not over all positions in the balls. Vertices that also slide along
the surface lower the energy further, but by taking the surface away from the true one: on the
noisy bunny (75 k to 1.2 M triangles, noise and `epsilon` 0.25 times the mean edge length) the
offsets end 1.5 to 1.6 times closer to the clean surface, with 1.4 times smaller normal errors
and better triangles, in about 100 iterations at every size where sliding took 242 to 820
(see the user manual). With the box bound (voxel cells, whose terraces the vertices must slide
off), the accurate objective and the paper's methods the vertices slide; `tangential_motion`
chooses either way.
Vertices with no normal (at triangles folded in the smoothed start, on creases) slide in any case.

<b>Slivers.</b> A hinge of the bending energy costs less the shorter its edge and the flatter
its triangles, so the energy alone ends with needles and caps of angles near 0 degrees. A
barrier is added to it: with `q = 4 sqrt(3) A / (l1^2 + l2^2 + l3^2)` a triangle's quality (1
when equilateral, `A` its area, `l` its edges) and `q0` about that of a needle with a 3 degree
angle, each triangle with `q < q0` adds `w (q0 / (q + q0 / 100) - 1)^2`, `w` the
`sliver_barrier_weight`. Better triangles are left alone, so that the shape and the bending
energy reached do not change; triangles degenerate in the input are left out, as in the energy.
`sliver_barrier_weight(0)` minimizes the paper's energy alone.

<b>Creases.</b> The bending energy rounds every crease as far as the bound lets it. Edges marked
in `edge_is_constrained_map`, or detected by `feature_angle`, are creases kept sharp: the energy
has no hinge across them, the curves they form are faired as curves within the same bounds (a
second-difference term per point on exactly two of them), and their points slide freely in their
balls, as they have no surface normal; a point on one crease edge or on three or more (an end, a
corner) is faired by its surfaces alone. The detection compares the face normals after a
guided filter (each face guided by the mean normal of the most consistent patch that holds it),
which averages the noise on each side of a crease and keeps the two sides apart, down to the
45 degrees of a chamfer: an edge is a crease where they are more than the angle apart and more
than 1.5 times the smaller angle across each face's other edges; curves that end freely after
fewer than 8 edges, and closed curves and clusters of fewer, are dropped, and curves that detour
by a triangle or around a vertex off their line are straightened, judged at smoothed points (a
detour round a vertex is judged across the crease too, by the planes of its two sides). On
seventeen noisy CAD parts (`benchmark/fairing_features`, noise and `epsilon` 0.25 times the mean
edge length) `feature_angle(30)` finds 86 to 100 % of the edges sharper than 40 degrees on
thirteen of them, chamfers, gear teeth and turned shafts among them, with at most 7 % of what it
marks no edge sharper than 20 degrees, and its mean normal error is 0.08 to 0.41 times the
default call's there; on parts of few, short or close sharp edges (a turbine, a thin blade, a
plate with small holes) it finds 3 to 57 % (see the user manual).

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
iteration relatively, on average over the last 50 iterations (quasi-Newton method, which also
waits until what is left to gain, extrapolated from the last two such windows, is at most 1 % of
the energy, and, along the normals, until what the surface has left to move across itself is at
most 0.5 % of `epsilon`) or the last three (the paper's methods), when no feasible direction
decreases it, or after `number_of_iterations` iterations.

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
- `feature_angle` not strictly between 0 and 180 degrees, or NaN;
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
  \cgalParamNBegin{tangential_motion}
    \cgalParamDescription{whether the vertices may also slide along the surface, rather than
                          move along the normals of the smoothed start only (see above)}
    \cgalParamType{bool}
    \cgalParamDefault{`false` with `QUASI_NEWTON`, the ball bound and `Constrained_fairing_objective::FAIREST`, `true` otherwise}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_constrained_map}
    \cgalParamDescription{a property map from edges to `bool`: the edges between two faces
                          marked `true` are creases, kept sharp (see "Creases" above); with
                          `feature_angle`, the edges it detects are also set to `true` in it if
                          it is writable, once the call succeeded. With a face range, a crease's
                          curve ends where it leaves the faces that take part}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool`
                   as value type}
    \cgalParamDefault{no edge is a crease, unless `feature_angle` is given}
  \cgalParamNEnd
  \cgalParamNBegin{feature_angle}
    \cgalParamDescription{detects the creases, kept sharp (see "Creases" above): the edges
                          across which the guided filtered face normals are more than this
                          many degrees apart}
    \cgalParamType{double, strictly between 0 and 180}
    \cgalParamDefault{unset: no detection}
  \cgalParamNEnd
  \cgalParamNBegin{energy_decrease_threshold}
    \cgalParamDescription{the stopping threshold on the relative energy decrease per
                          iteration (averaged over 50 iterations for `QUASI_NEWTON`, three for the
                          paper's methods; `QUASI_NEWTON` also waits until the extrapolated
                          decrease still to come is at most 1 % of the energy and, along the
                          normals, the surface's motion still to come at most 0.5 % of
                          `epsilon`); `0` runs all `number_of_iterations` iterations}
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
    \cgalParamDescription{called after each iteration on the path to the result with its number
                          (from 1, in order) and the objective reached, which decreases from call
                          to call; returning `false` stops the run, and the mesh gets that
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
