// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangle mesh seen as flat index arrays: its triangles and its edge stencils
// (an edge with the vertices opposite to it). Everything else in the solver works on these
// arrays and on an n x 3 matrix of vertex coordinates.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HINGE_MESH_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HINGE_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// Vertex coordinates, one row per vertex: the paper's point x in R^{3n}.
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

inline Eigen::Map<const Eigen::Vector3d> point(const Points& X, std::size_t i)
{
  return Eigen::Map<const Eigen::Vector3d>(X.data() + 3 * i);
}

inline Eigen::Map<Eigen::Vector3d> point(Points& X, std::size_t i)
{
  return Eigen::Map<Eigen::Vector3d>(X.data() + 3 * i);
}

// The scale, a power of two, at which the energy and its Hessian are evaluated: 1 when the
// largest coordinate of X is within [2^-100, 2^100], where squared areas of any mesh that is
// not a single point fit in double; otherwise the one that brings it into [1/2, 1), for meshes
// in kilometres or nanometres of absurd units. A power of two scales every intermediate
// result exactly.
inline double unit_scale(const Points& X)
{
  const double largest = X.size() > 0 ? X.cwiseAbs().maxCoeff() : 0;
  int exponent = 0;
  std::frexp(largest, &exponent);
  if(!(largest > 0) || (exponent > -100 && exponent <= 100))
    return 1;
  return std::ldexp(1., (std::max)(-1000, (std::min)(1000, -exponent)));
}

// An interior edge (v[0], v[1]) with its two triangles (v[0], v[1], v[2]) and (v[1], v[0], v[3]),
// both oriented as in the mesh; f[0] and f[1] are their indices in Hinge_mesh::triangles.
struct Hinge
{
  std::array<std::size_t, 4> v;
  std::array<std::size_t, 2> f;
};

// A border edge (v[0], v[1]) with its one triangle (v[0], v[1], v[2]).
struct Border_edge
{
  std::array<std::size_t, 3> v;
};

// The arrays are sorted by vertex indices, so that they depend only on the order of the
// vertices, not on how the graph stores its faces and edges: two mesh data structures
// holding the same mesh give bit-identical results.
struct Hinge_mesh
{
  std::size_t number_of_vertices = 0;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<Hinge> hinges;
  std::vector<Border_edge> border_edges;

  // `vertex_index` maps each vertex of the triangle mesh `tmesh` to [0, num_vertices(tmesh)).
  template <typename TriangleMesh, typename VertexIndexMap>
  Hinge_mesh(const TriangleMesh& tmesh, const VertexIndexMap& vertex_index)
    : number_of_vertices(static_cast<std::size_t>(num_vertices(tmesh)))
  {
    using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
    auto id = [&](auto v) { return static_cast<std::size_t>(get(vertex_index, v)); };

    // Each triangle starts at its smallest vertex index, orientation kept.
    std::vector<std::pair<std::array<std::size_t, 3>, face_descriptor> > sorted;
    sorted.reserve(static_cast<std::size_t>(num_faces(tmesh)));
    for(face_descriptor f : faces(tmesh))
    {
      const auto h = halfedge(f, tmesh);
      std::array<std::size_t, 3> t = {id(source(h, tmesh)), id(target(h, tmesh)),
                                      id(target(next(h, tmesh), tmesh))};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      sorted.emplace_back(t, f);
    }
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    auto face_index = get(CGAL::dynamic_face_property_t<std::size_t>(), tmesh);
    triangles.reserve(sorted.size());
    for(const auto& t : sorted)
    {
      put(face_index, t.second, triangles.size());
      triangles.push_back(t.first);
    }

    for(auto e : edges(tmesh))
    {
      auto h = halfedge(e, tmesh);
      if(is_border(h, tmesh))
        h = opposite(h, tmesh);
      const std::size_t a = id(source(h, tmesh)), b = id(target(h, tmesh));
      const std::size_t c = id(target(next(h, tmesh), tmesh));
      if(is_border_edge(h, tmesh))
      {
        border_edges.push_back(Border_edge{{a, b, c}});
        continue;
      }
      const std::size_t d = id(target(next(opposite(h, tmesh), tmesh), tmesh));
      const std::size_t f = get(face_index, face(h, tmesh)), g = get(face_index, face(opposite(h, tmesh), tmesh));
      hinges.push_back(a < b ? Hinge{{a, b, c, d}, {f, g}} : Hinge{{b, a, d, c}, {g, f}});
    }
    auto by_vertices = [](const auto& x, const auto& y) { return x.v < y.v; };
    std::sort(hinges.begin(), hinges.end(), by_vertices);
    std::sort(border_edges.begin(), border_edges.end(), by_vertices);
  }
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HINGE_MESH_H
