// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input contract of constrained_fairing(), checked before anything is computed, in the
// order of Constrained_fairing_defect: the mesh (mesh_error), its coordinates, epsilon, the
// fidelity weight, the per-vertex bounds (Vertex_bounds::read, with the values it reads), the
// input positions in their boxes, and the area. Meshes come from files, so every defect a file
// can hold is a recoverable error, in release builds too, with its kind and a message that
// names it. Vertices and faces are named by their position, from 0, in vertices(tmesh) and
// faces(tmesh): for a mesh read from a file, their order in the file.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INPUT_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INPUT_CHECK_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_result.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Vertex_table.h>

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// A defect and its message; converts to true when there is one.
struct Input_error
{
  Constrained_fairing_defect defect = Constrained_fairing_defect::NONE;
  std::string message;

  explicit operator bool() const { return defect != Constrained_fairing_defect::NONE; }
};

inline Input_error epsilon_error(double epsilon)
{
  if(std::isfinite(epsilon) && epsilon > 0)
    return {};
  return {Constrained_fairing_defect::INVALID_EPSILON,
          "epsilon must be a positive finite number (got " + std::to_string(epsilon) + ")"};
}

inline Input_error fidelity_weight_error(double mu)
{
  if(std::isfinite(mu) && mu >= 0)
    return {};
  return {Constrained_fairing_defect::INVALID_FIDELITY_WEIGHT,
          "fidelity_weight must be finite and non-negative (" + std::to_string(mu) + ")"};
}

inline Input_error sliver_barrier_weight_error(double nu)
{
  if(std::isfinite(nu) && nu >= 0)
    return {};
  return {Constrained_fairing_defect::INVALID_SLIVER_BARRIER_WEIGHT,
          "sliver_barrier_weight must be finite and non-negative (" + std::to_string(nu) + ")"};
}

// The links that the walks below rely on: next() is a permutation whose cycles are the faces
// and the holes, and opposite() pairs halfedges with swapped ends. CGAL::is_valid_polygon_mesh()
// also demands that no vertex be isolated, which this contract allows, and that the faces
// around a vertex form one fan, which gets its own message below.
template <typename TriangleMesh>
bool is_valid_structure(const TriangleMesh& tmesh)
{
  using Traits = boost::graph_traits<TriangleMesh>;
  for(auto h : halfedges(tmesh))
  {
    const auto n = next(h, tmesh), o = opposite(h, tmesh);
    if(n == Traits::null_halfedge() || o == Traits::null_halfedge() || o == h || opposite(o, tmesh) != h ||
       prev(n, tmesh) != h || target(h, tmesh) == Traits::null_vertex() ||
       target(h, tmesh) != target(opposite(n, tmesh), tmesh) || face(n, tmesh) != face(h, tmesh))
      return false;
  }
  for(auto f : faces(tmesh))
    if(halfedge(f, tmesh) == Traits::null_halfedge() || face(halfedge(f, tmesh), tmesh) != f)
      return false;
  return true;
}

// Empty, broken, non-triangle, non-manifold, inconsistently oriented or too large meshes;
// `vertex_index` numbers the vertices from 0 to num_vertices(tmesh) - 1. The energy's dihedral
// angles need each interior edge to join exactly two triangles that run through it in opposite
// directions; a halfedge structure ensures this for the faces it links across an edge, but two
// of its faces may still share two vertices through separate edges.
template <typename TriangleMesh, typename VertexIndexMap>
Input_error mesh_error(const TriangleMesh& tmesh, const VertexIndexMap& vertex_index)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using D = Constrained_fairing_defect;
  auto id = [&](auto v) { return std::to_string(get(vertex_index, v)); };

  if(num_vertices(tmesh) == 0)
    return {D::EMPTY_MESH, "the mesh is empty"};
  if(num_faces(tmesh) == 0)
    return {D::NO_FACES, "the mesh has no faces"};
  if(!is_valid_structure(tmesh))
    return {D::BROKEN_STRUCTURE,
            "the mesh's halfedge structure is broken (its next, prev, opposite, target and face links disagree)"};

  // Each face's three directed edges, as (smaller vertex, larger vertex, face, halfedge).
  struct Face_edge
  {
    std::size_t a, b, face;
    halfedge_descriptor h;
  };
  std::size_t face_number = 0;
  for(auto f : faces(tmesh))
  {
    const auto around = halfedges_around_face(halfedge(f, tmesh), tmesh);
    const auto degree = std::distance(around.begin(), around.end());
    if(degree != 3)
      return {D::NOT_TRIANGLE, "face " + std::to_string(face_number) + " has " + std::to_string(degree) +
                                  " vertices: the mesh must be made of triangles"};
    ++face_number;
  }
  // Sorted by (a, b, face), a by a counting sort (Vertex_table.h).
  Vertex_table<Face_edge> edges_by_vertex(static_cast<std::size_t>(num_vertices(tmesh)), [&](const auto& add) {
    std::size_t number = 0;
    for(auto f : faces(tmesh))
    {
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tmesh), tmesh))
      {
        const std::size_t s = get(vertex_index, source(h, tmesh)), t = get(vertex_index, target(h, tmesh));
        add((std::min)(s, t), Face_edge{(std::min)(s, t), (std::max)(s, t), number, h});
      }
      ++number;
    }
  });
  edges_by_vertex.sort_rows(
    [](const Face_edge& x, const Face_edge& y) { return x.b != y.b ? x.b < y.b : x.face < y.face; });
  const std::vector<Face_edge>& face_edges = edges_by_vertex.items;
  for(std::size_t i = 0, j = 0; i < face_edges.size(); i = j)
  {
    while(j < face_edges.size() && face_edges[j].a == face_edges[i].a && face_edges[j].b == face_edges[i].b)
      ++j;
    const Face_edge& x = face_edges[i];
    // the message's words, written only for a defect
    const auto edge = [&x] { return "vertices " + std::to_string(x.a) + " and " + std::to_string(x.b); };
    if(j - i > 2)
      return {D::NON_MANIFOLD_EDGE,
              "the edge between " + edge() + " has " + std::to_string(j - i) + " faces (a non-manifold edge)"};
    if(j - i < 2)
      continue;
    const Face_edge& y = face_edges[i + 1];
    if(opposite(x.h, tmesh) == y.h)
      continue;
    if(target(x.h, tmesh) == target(y.h, tmesh))
      return {D::INCONSISTENT_ORIENTATION, "faces " + std::to_string(x.face) + " and " + std::to_string(y.face) +
                                              " are oriented inconsistently: both run from vertex " +
                                              id(source(x.h, tmesh)) + " to vertex " + id(target(x.h, tmesh))};
    return {D::NON_MANIFOLD_EDGE, "faces " + std::to_string(x.face) + " and " + std::to_string(y.face) + " share " +
                                    edge() + " through two different edges (a non-manifold edge)"};
  }

  std::vector<halfedge_descriptor> pinched;
  non_manifold_vertices(tmesh, std::back_inserter(pinched));
  if(!pinched.empty())
  {
    std::size_t first = (std::numeric_limits<std::size_t>::max)();
    for(halfedge_descriptor h : pinched)
      first = (std::min)(first, static_cast<std::size_t>(get(vertex_index, target(h, tmesh))));
    return {D::NON_MANIFOLD_VERTEX, "vertex " + std::to_string(first) + " is non-manifold: its faces form more than one fan"};
  }

  // The solver numbers vertices and face corners with 32 bits.
  if(static_cast<std::size_t>(num_vertices(tmesh)) > (std::numeric_limits<Index>::max)() ||
     static_cast<std::size_t>(num_faces(tmesh)) > Hinge_mesh::max_faces)
    return {D::MESH_TOO_LARGE, "the mesh is too large: at most " + std::to_string((std::numeric_limits<Index>::max)()) +
                                 " vertices and " + std::to_string(Hinge_mesh::max_faces) + " faces"};
  return {};
}

// X0 holds the points of the vertices; `number(i)` names vertex i in the message.
template <typename Number>
Input_error coordinates_error(const Points& X0, const Number& number)
{
  for(Eigen::Index i = 0; i < X0.rows(); ++i)
    if(!X0.row(i).allFinite())
      return {Constrained_fairing_defect::NON_FINITE_COORDINATE,
              "vertex " + std::to_string(number(static_cast<std::size_t>(i))) + " has a NaN or infinite coordinate"};
  return {};
}

// `outside` is the first vertex outside its box in the order of the user's vertices, or the
// number of vertices if there is none; `number(i)` names vertex i in the message.
template <typename Number>
Input_error outside_box_error(std::size_t outside, std::size_t n, const Number& number)
{
  if(outside >= n)
    return {};
  return {Constrained_fairing_defect::OUTSIDE_BOX, "vertex " + std::to_string(number(outside)) + " lies outside its box"};
}

// `defined`: whether the energy is defined (Bending_energy::is_defined()), which it is not
// only if every triangle has zero area in double.
inline Input_error area_error(bool defined)
{
  if(defined)
    return {};
  return {Constrained_fairing_defect::NO_AREA, "all triangles of the mesh have zero area"};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_INPUT_CHECK_H
