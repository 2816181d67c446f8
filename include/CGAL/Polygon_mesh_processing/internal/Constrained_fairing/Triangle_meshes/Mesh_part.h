// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_PART_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_PART_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The part of `tmesh` that takes part in a call: its vertices (in the order `vertices(tmesh)`
// lists them), those of them that stay, the triangles whose hinges may count, and which
// hinges do. With no face range: the whole mesh, every vertex free and every hinge counted.
// With a face range R: a vertex moves when all its faces are in R; the triangles are R and its
// neighbours across an edge, and a hinge counts when one of its four vertices moves.
template <typename TriangleMesh>
class Mesh_part
{
public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  // `feature_angle` detects creases (Feature_edges.h).
  static constexpr bool detects_creases = true;

  // `is_constrained(v)`: whether the user fixed vertex v.
  // The whole mesh: no list is stored, the vertices are those of `tmesh` in their order.
  template <typename IsConstrained>
  Mesh_part(const TriangleMesh& tmesh, const IsConstrained& is_constrained)
    : m_tmesh(tmesh), m_size(static_cast<std::size_t>(num_vertices(tmesh)))
  {
    m_fixed.reserve(m_size);
    for(auto v : vertices(tmesh))
      m_fixed.push_back(is_constrained(v));
  }

  // A face range; `vertex_index` numbers the vertices in the order of vertices(tmesh).
  template <typename FaceRange, typename VertexIndexMap, typename IsConstrained>
  Mesh_part(const FaceRange& region, const TriangleMesh& tmesh, const VertexIndexMap& vertex_index,
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
      bool moves = !is_constrained(v);
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

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_PART_H
