// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_CONSTRAINED_FAIRING_RESULT_H
#define CGAL_PMP_CONSTRAINED_FAIRING_RESULT_H

#include <cstddef>
#include <string>

namespace CGAL {
namespace Polygon_mesh_processing {

/// \ingroup PkgConstrainedFairingRef
/// How a call to `constrained_fairing()` ended.
enum class Constrained_fairing_status
{
  /// The relative energy decrease fell below the threshold, or no feasible direction
  /// decreases the energy any more. The mesh holds the result.
  CONVERGED,
  /// `number_of_iterations` iterations were done. The mesh holds the last iterate.
  ITERATION_LIMIT_REACHED,
  /// The iteration callback returned `false`. The mesh holds the last iterate.
  CANCELLED,
  /// The input was rejected before anything was done; `message` says why. The mesh is untouched.
  INVALID_INPUT,
  /// The sparse linear solver could not factorize the Hessian approximation. The mesh is untouched.
  LINEAR_SOLVER_FAILED
};

/// \ingroup PkgConstrainedFairingRef
/// The defect of an input that `constrained_fairing()` rejected, one per check of its input
/// contract, in the order the checks are made; the result's message says the same in words,
/// naming the first vertex or face concerned.
enum class Constrained_fairing_defect
{
  /// the input was accepted
  NONE,
  /// the mesh has no vertex
  EMPTY_MESH,
  /// the mesh has no face
  NO_FACES,
  /// a face of a polygon soup (a file the command-line tool reads, the arrays of the Python
  /// module) has fewer than three vertices, or refers to a vertex that does not exist or to
  /// one vertex twice; `constrained_fairing()` itself, given a halfedge mesh, never reports it
  INVALID_FACE,
  /// the `next()`, `prev()`, `opposite()`, `target()` and `face()` links disagree
  BROKEN_STRUCTURE,
  /// a face is not a triangle
  NOT_TRIANGLE,
  /// an edge with more than two faces, or two faces sharing two vertices through two edges
  NON_MANIFOLD_EDGE,
  /// two neighbouring faces run through their shared vertices in the same direction
  INCONSISTENT_ORIENTATION,
  /// the faces around a vertex form more than one fan
  NON_MANIFOLD_VERTEX,
  /// more vertices or faces than the solver's 32-bit indices hold
  MESH_TOO_LARGE,
  /// a vertex has a NaN or infinite coordinate
  NON_FINITE_COORDINATE,
  /// `epsilon` is not a positive finite number
  INVALID_EPSILON,
  /// `fidelity_weight` is negative, NaN or infinite
  INVALID_FIDELITY_WEIGHT,
  /// `sliver_barrier_weight` is negative, NaN or infinite
  INVALID_SLIVER_BARRIER_WEIGHT,
  /// `feature_angle` is not a number of degrees strictly between 0 and 180, or was given to
  /// `constrained_fairing_of_interfaces()`, which detects no creases
  INVALID_FEATURE_ANGLE,
  /// box parameters were given with `deviation_bound(Deviation_bound::BALL)`
  BOX_WITH_BALL,
  /// a box half-extent (`box_half_extents`, `vertex_box_half_extents_map`) is negative, NaN or infinite
  INVALID_BOX_EXTENTS,
  /// a per-vertex tolerance is negative, NaN or infinite
  INVALID_TOLERANCE,
  /// a box centre has a NaN or infinite coordinate
  INVALID_BOX_CENTER,
  /// an input position lies outside its box
  OUTSIDE_BOX,
  /// every triangle has zero area
  NO_AREA,
  /// a point set has no more points than `number_of_neighbors`
  TOO_FEW_POINTS,
  /// `number_of_neighbors` is less than 3
  INVALID_NUMBER_OF_NEIGHBORS,
  /// two points of a point set coincide
  DUPLICATE_POINTS,
  /// a given normal is zero, NaN or infinite
  INVALID_NORMAL,
  /// no point of a point set has neighbours around it in its tangent plane: the points are
  /// all on one line
  NO_SURFACE,
  /// the method needs hinges, which a point set has not (the paper's methods)
  METHOD_NEEDS_MESH
};

/// \ingroup PkgConstrainedFairingRef
/// What `constrained_fairing()` did. Converts to `true` when the mesh holds a faired result:
/// every vertex within the bound and the energy not higher than at the start.
struct Constrained_fairing_result
{
  /// how the call ended
  Constrained_fairing_status status = Constrained_fairing_status::INVALID_INPUT;
  /// a human readable reason when `status` is a failure, empty otherwise
  std::string message;
  /// what is wrong with the input when `status` is `INVALID_INPUT`, `NONE` otherwise
  Constrained_fairing_defect defect = Constrained_fairing_defect::NONE;
  /// iterations on the path to the result, as the `iteration_callback` heard them: accepted
  /// steps of the quasi-Newton method (the default); a Cauchy step followed by a Newton step
  /// for `ACTIVE_SET_NEWTON`; a Cauchy step for `PROJECTED_GRADIENT`. The steps of a round of
  /// fold repair that do not get below the objective reached before it are not on that path
  /// and count only in `number_of_energy_evaluations`.
  std::size_t number_of_iterations = 0;
  /// conjugate gradient iterations over all Newton steps (`ACTIVE_SET_NEWTON` only)
  std::size_t number_of_cg_iterations = 0;
  /// evaluations of the energy, with or without its gradient, over all the work done: the main
  /// cost of the default method
  std::size_t number_of_energy_evaluations = 0;
  /// the objective's value on the input mesh: its bending energy plus the barrier against
  /// slivers (`sliver_barrier_weight`), plus the fidelity term for
  /// `Constrained_fairing_objective::ACCURATE`
  double initial_energy = 0;
  /// the objective's value on the output mesh, made of the same terms
  double final_energy = 0;
  /// the bending energy of the input mesh, the paper's energy alone
  double initial_bending_energy = 0;
  /// the bending energy of the output mesh
  double final_bending_energy = 0;
  /// the largest Euclidean distance of an output vertex to its input position
  double max_deviation = 0;
  /// the vertices that could move and ended on the boundary of their ball or box
  std::size_t number_of_vertices_at_bound = 0;
  /// the vertices that did not move because they are fixed (`vertex_is_constrained_map`, a
  /// tolerance of 0) or, for a face range, outside it or on its border
  std::size_t number_of_fixed_vertices = 0;
  /// the faces still turned over against their neighbours at the end (the normal opposite the
  /// sum of the neighbours' area-weighted normals), among those with a vertex that could move
  std::size_t number_of_folded_faces = 0;
  /// the folded faces that the fold repair undid: after the descent, the vertices of the folds
  /// and their neighbours are re-seeded and the descent resumes, kept if the objective ends
  /// lower, and repeated (three rounds at most) while each round unfolds at least half of the
  /// folded faces it started from
  std::size_t number_of_unfolded_faces = 0;
  /// the edges kept as creases: those of `edge_is_constrained_map` and those the detection of
  /// `feature_angle` found; the energy has no hinge across them
  std::size_t number_of_feature_edges = 0;
  /// the interior edges left out of the energy because one of their two triangles is
  /// degenerate (of nearly zero area) in the input
  std::size_t number_of_degenerate_edges = 0;
  /// the points of a point set with no usable neighbourhood (outliers far from the others,
  /// or whose neighbours are on a line), kept where they are; counted in
  /// `number_of_fixed_vertices` too
  std::size_t number_of_isolated_points = 0;

  /// `true` when the mesh holds a faired result
  explicit operator bool() const
  {
    return status == Constrained_fairing_status::CONVERGED ||
           status == Constrained_fairing_status::ITERATION_LIMIT_REACHED ||
           status == Constrained_fairing_status::CANCELLED;
  }
};

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_CONSTRAINED_FAIRING_RESULT_H
