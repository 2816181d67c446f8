// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input contract's part that a halfedge mesh can break, checked first: not empty, linked
// consistently, triangles, manifold, consistently oriented, and within the solver's 32-bit
// indices. Meshes come from files, so every defect a file can hold is a recoverable error, in
// release builds too (Input_defects.h). Vertices and faces are named by their position, from 0,
// in vertices(tmesh) and faces(tmesh): for a mesh read from a file, their order in the file.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

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
  const auto id = [&](auto v) { return static_cast<std::size_t>(get(vertex_index, v)); };

  if(num_vertices(tmesh) == 0)
    return empty_mesh_error();
  if(num_faces(tmesh) == 0)
    return no_faces_error();
  if(!is_valid_structure(tmesh))
    return broken_structure_error();

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
      return not_triangle_error(face_number, static_cast<std::size_t>(degree));
    ++face_number;
  }
  // Sorted by (a, b, face), a by a counting sort (Rows_by_vertex.h).
  Rows_by_vertex<Face_edge> edges_by_vertex(static_cast<std::size_t>(num_vertices(tmesh)), [&](const auto& add) {
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
    if(j - i > 2)
      return crowded_edge_error(x.a, x.b, j - i);
    if(j - i < 2)
      continue;
    const Face_edge& y = face_edges[i + 1];
    if(opposite(x.h, tmesh) == y.h)
      continue;
    if(target(x.h, tmesh) == target(y.h, tmesh))
      return inconsistent_orientation_error(x.face, y.face, id(source(x.h, tmesh)), id(target(x.h, tmesh)));
    return split_edge_error(x.face, y.face, x.a, x.b);
  }

  std::vector<halfedge_descriptor> pinched;
  non_manifold_vertices(tmesh, std::back_inserter(pinched));
  if(!pinched.empty())
  {
    std::size_t first = (std::numeric_limits<std::size_t>::max)();
    for(halfedge_descriptor h : pinched)
      first = (std::min)(first, static_cast<std::size_t>(get(vertex_index, target(h, tmesh))));
    return non_manifold_vertex_error(first);
  }

  // The solver numbers vertices and face corners with 32 bits.
  if(static_cast<std::size_t>(num_vertices(tmesh)) > (std::numeric_limits<Index>::max)() ||
     static_cast<std::size_t>(num_faces(tmesh)) > Hinge_mesh::max_faces)
    return mesh_too_large_error((std::numeric_limits<Index>::max)(), Hinge_mesh::max_faces);
  return {};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_CHECK_H
