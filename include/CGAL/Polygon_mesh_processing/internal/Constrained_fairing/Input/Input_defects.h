// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input contract's defects, each with the one function that makes its error and message:
// every check names a defect through these, whether it checks a mesh (Mesh_check.h), a
// multi-label surface (Interface_check.h), the values of a call (Value_check.h) or a polygon
// soup before it becomes a mesh (Polygon_soup_check.h), so that a defect reads the same
// whichever path found it.
// Vertices and faces are named by their position, from 0, in the user's order.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INPUT_DEFECTS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INPUT_DEFECTS_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

using Defect = Constrained_fairing_defect;

// A defect and its message; converts to true when there is one.
struct Input_error
{
  Defect defect = Defect::NONE;
  std::string message;

  explicit operator bool() const { return defect != Defect::NONE; }
};

namespace defect_message {

inline std::string vertex(std::size_t v) { return "vertex " + std::to_string(v); }

// The shortest decimal text that reads back as `x` ("0.01", "-1e-07", "nan"), not
// std::to_string's fixed six decimals, which show -1e-07 as -0.000000.
inline std::string number(double x)
{
  char text[32];
  for(int digits = 6; digits <= 17; ++digits)
  {
    std::snprintf(text, sizeof(text), "%.*g", digits, x);
    if(!std::isfinite(x) || std::strtod(text, nullptr) == x)
      break;
  }
  return text;
}
inline std::string faces(std::size_t f, std::size_t g)
{
  return "faces " + std::to_string(f) + " and " + std::to_string(g);
}
inline std::string vertices(std::size_t a, std::size_t b)
{
  return "vertices " + std::to_string(a) + " and " + std::to_string(b);
}

} // namespace defect_message

inline Input_error empty_mesh_error() { return {Defect::EMPTY_MESH, "the mesh is empty"}; }

inline Input_error no_faces_error() { return {Defect::NO_FACES, "the mesh has no faces"}; }

inline Input_error broken_structure_error()
{
  return {Defect::BROKEN_STRUCTURE,
          "the mesh's halfedge structure is broken (its next, prev, opposite, target and face links disagree)"};
}

// A face of a soup with fewer than three corners.
inline Input_error too_few_corners_error(std::size_t f, std::size_t corners)
{
  return {Defect::INVALID_FACE, "face " + std::to_string(f) + " has " + std::to_string(corners) + " vertices"};
}

// A face of a soup that names vertex `v` (as the user gave it, possibly negative) of `n`.
template <typename Integer>
Input_error missing_vertex_error(std::size_t f, Integer v, std::size_t n)
{
  return {Defect::INVALID_FACE, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                  ", but there are " + std::to_string(n) + " vertices"};
}

inline Input_error repeated_vertex_error(std::size_t f, std::size_t v)
{
  return {Defect::INVALID_FACE, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " twice"};
}

// A triangle of a multi-label surface with the same label on both sides.
inline Input_error same_labels_error(std::size_t f)
{
  return {Defect::INVALID_FACE, "face " + std::to_string(f) + " has the same label on both sides"};
}

inline Input_error not_triangle_error(std::size_t f, std::size_t corners)
{
  return {Defect::NOT_TRIANGLE, "face " + std::to_string(f) + " has " + std::to_string(corners) +
                             " vertices: the mesh must be made of triangles"};
}

// More than two faces on the edge between vertices a and b.
inline Input_error crowded_edge_error(std::size_t a, std::size_t b, std::size_t number_of_faces)
{
  return {Defect::NON_MANIFOLD_EDGE, "the edge between " + defect_message::vertices(a, b) + " has " +
                                  std::to_string(number_of_faces) + " faces (a non-manifold edge)"};
}

// Two faces that share vertices a and b through two different edges of a halfedge mesh.
inline Input_error split_edge_error(std::size_t f, std::size_t g, std::size_t a, std::size_t b)
{
  return {Defect::NON_MANIFOLD_EDGE, defect_message::faces(f, g) + " share " + defect_message::vertices(a, b) +
                                  " through two different edges (a non-manifold edge)"};
}

// Faces f and g both run from vertex `from` to vertex `to`.
inline Input_error inconsistent_orientation_error(std::size_t f, std::size_t g, std::size_t from, std::size_t to)
{
  return {Defect::INCONSISTENT_ORIENTATION, defect_message::faces(f, g) +
                                              " are oriented inconsistently: both run from " +
                                              defect_message::vertex(from) + " to " + defect_message::vertex(to)};
}

inline Input_error non_manifold_vertex_error(std::size_t v)
{
  return {Defect::NON_MANIFOLD_VERTEX,
          defect_message::vertex(v) + " is non-manifold: its faces form more than one fan"};
}

inline Input_error mesh_too_large_error(std::size_t max_vertices, std::size_t max_faces)
{
  return {Defect::MESH_TOO_LARGE, "the mesh is too large: at most " + std::to_string(max_vertices) + " vertices and " +
                               std::to_string(max_faces) + " faces"};
}

inline Input_error non_finite_coordinate_error(std::size_t v)
{
  return {Defect::NON_FINITE_COORDINATE, defect_message::vertex(v) + " has a NaN or infinite coordinate"};
}

inline Input_error invalid_epsilon_error(double epsilon)
{
  return {Defect::INVALID_EPSILON, "epsilon must be a positive finite number (got " + defect_message::number(epsilon) + ")"};
}

inline Input_error invalid_fidelity_weight_error(double mu)
{
  return {Defect::INVALID_FIDELITY_WEIGHT,
          "fidelity_weight must be finite and non-negative (" + defect_message::number(mu) + ")"};
}

inline Input_error invalid_sliver_barrier_weight_error(double nu)
{
  return {Defect::INVALID_SLIVER_BARRIER_WEIGHT,
          "sliver_barrier_weight must be finite and non-negative (" + defect_message::number(nu) + ")"};
}

inline Input_error invalid_feature_angle_error(double degrees)
{
  return {Defect::INVALID_FEATURE_ANGLE,
          "feature_angle must be a number of degrees strictly between 0 and 180 (" + defect_message::number(degrees) + ")"};
}

inline Input_error feature_angle_without_creases_error()
{
  return {Defect::INVALID_FEATURE_ANGLE,
          "feature_angle does not apply to a multi-label surface, whose junction lines are its curves"};
}

inline Input_error box_with_ball_error()
{
  return {Defect::BOX_WITH_BALL, "box half-extents or centres were given with the ball bound"};
}

// `whose`: "box_half_extents" for the uniform ones, "the box half-extents of vertex v" otherwise.
inline Input_error invalid_box_extents_error(const std::string& whose, double hx, double hy, double hz)
{
  return {Defect::INVALID_BOX_EXTENTS, whose + " must be finite and non-negative (" + defect_message::number(hx) + ", " +
                                    defect_message::number(hy) + ", " + defect_message::number(hz) + ")"};
}

inline Input_error invalid_tolerance_error(std::size_t v, double tolerance)
{
  return {Defect::INVALID_TOLERANCE,
          defect_message::vertex(v) + " has a negative, NaN or infinite tolerance (" + defect_message::number(tolerance) + ")"};
}

inline Input_error invalid_box_center_error(std::size_t v)
{
  return {Defect::INVALID_BOX_CENTER,
          "the box centre of " + defect_message::vertex(v) + " has a NaN or infinite coordinate"};
}

inline Input_error outside_box_error(std::size_t v)
{
  return {Defect::OUTSIDE_BOX, defect_message::vertex(v) + " lies outside its box"};
}

inline Input_error no_area_error() { return {Defect::NO_AREA, "all triangles of the mesh have zero area"}; }

inline Input_error too_few_points_error(std::size_t n, std::size_t k)
{
  return {Defect::TOO_FEW_POINTS, "the point set has " + std::to_string(n) + " points, not more than its " +
                                    std::to_string(k) + " neighbours (number_of_neighbors)"};
}

inline Input_error invalid_number_of_neighbors_error(std::size_t k)
{
  return {Defect::INVALID_NUMBER_OF_NEIGHBORS,
          "number_of_neighbors is " + std::to_string(k) + ", it must be at least 3"};
}

inline Input_error duplicate_points_error(std::size_t i, std::size_t j)
{
  return {Defect::DUPLICATE_POINTS, "points " + std::to_string((std::min)(i, j)) + " and " +
                                      std::to_string((std::max)(i, j)) + " coincide"};
}

inline Input_error invalid_normal_error(std::size_t i)
{
  return {Defect::INVALID_NORMAL, "the normal of point " + std::to_string(i) + " is zero, NaN or infinite"};
}

inline Input_error no_surface_error()
{
  return {Defect::NO_SURFACE, "no point has neighbours around it in its tangent plane: the points are on one line"};
}

inline Input_error method_needs_mesh_error()
{
  return {Defect::METHOD_NEEDS_MESH,
          "the paper's methods need a mesh's hinges; a point set is faired by QUASI_NEWTON (the default)"};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INPUT_DEFECTS_H
