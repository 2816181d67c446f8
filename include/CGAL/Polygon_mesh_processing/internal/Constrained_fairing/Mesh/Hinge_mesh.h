// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangle mesh seen as flat index arrays: its triangles and its hinges (an interior edge
// with its two triangles). Everything else in the solver works on these
// arrays and on an n x 3 matrix of vertex coordinates.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HINGE_MESH_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HINGE_MESH_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Curve_network.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// An interior edge from v[0] to v[1] with its two triangles, both oriented as in the mesh:
// f[0] runs along the edge from v[0] to v[1], f[1] from v[1] to v[0] (their indices in
// Hinge_mesh::triangles).
struct Hinge
{
  std::array<Index, 2> v;
  std::array<Index, 2> f;
};

// An edge as its two vertices, the smaller first, as the hinges hold theirs and the creases are
// kept (Feature_edges.h).
inline std::array<Index, 2> sorted_edge(Index a, Index b)
{
  return a < b ? std::array<Index, 2>{a, b} : std::array<Index, 2>{b, a};
}

// The arrays are sorted by vertex indices, so that they depend only on the order of the
// vertices, not on how the graph stores its faces and edges: two mesh data structures
// holding the same mesh give bit-identical results.
struct Hinge_mesh
{
  std::size_t number_of_vertices = 0;
  std::vector<std::array<Index, 3> > triangles;
  std::vector<Hinge> hinges;
  // A mesh's creases (Feature_edges.h): edges between two triangles with no hinge, smoothed and
  // faired as curves; empty on a multi-label surface, whose junction lines the interfaces'
  // hinges do not cross anyway.
  Curve_network creases;
  // Built from a triangle list: the position in `triangles` of each triangle of the list.
  std::vector<Index> positions_of_list;

  // The largest mesh the 32-bit indices hold (Bending_energy numbers face corners 3 f + k).
  static constexpr std::size_t max_faces = 0x55555555;

  // Triangles given as index triples into [0, number_of_vertices), oriented, and the hinges
  // between them as pairs {f, g} of positions in `triangle_list`, f running along the shared edge
  // from a to b and g from b to a: the surface of a soup, whose hinges its caller chose.
  Hinge_mesh(std::size_t number_of_vertices, const std::vector<std::array<Index, 3> >& triangle_list,
             const std::vector<std::array<Index, 2> >& hinge_faces)
    : number_of_vertices(number_of_vertices)
  {
    // Each triangle starts at its smallest vertex index, orientation kept.
    std::vector<std::pair<std::array<Index, 3>, Index> > sorted;
    sorted.reserve(triangle_list.size());
    for(std::size_t f = 0; f < triangle_list.size(); ++f)
    {
      std::array<Index, 3> t = triangle_list[f];
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      sorted.emplace_back(t, static_cast<Index>(f));
    }
    sort_by_vertex(sorted, number_of_vertices, [](const auto& t) { return t.first[0]; },
                   [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Index>& position = positions_of_list;
    position.resize(sorted.size());
    triangles.reserve(sorted.size());
    for(const auto& t : sorted)
    {
      position[t.second] = static_cast<Index>(triangles.size());
      triangles.push_back(t.first);
    }
    hinges.reserve(hinge_faces.size());
    for(const auto& fg : hinge_faces)
    {
      const Index f = position[fg[0]], g = position[fg[1]];
      // f's side that g runs the other way
      const auto& t = triangles[f];
      const auto& u = triangles[g];
      for(int c = 0; c < 3; ++c)
      {
        const Index a = t[std::size_t(c)], b = t[std::size_t((c + 1) % 3)];
        if(std::find(u.begin(), u.end(), a) != u.end() && std::find(u.begin(), u.end(), b) != u.end())
        {
          hinges.push_back(a < b ? Hinge{{a, b}, {f, g}} : Hinge{{b, a}, {g, f}});
          break;
        }
      }
    }
    sort_by_vertex(hinges, number_of_vertices, [](const Hinge& x) { return x.v[0]; },
                   [](const Hinge& x, const Hinge& y) { return x.v < y.v; });
  }

  // `vertex_index` maps each vertex of the triangle mesh `tmesh` to [0, num_vertices(tmesh)),
  // which has fewer than 2^32 vertices and at most `max_faces` faces.
  template <typename TriangleMesh, typename VertexIndexMap>
  Hinge_mesh(const TriangleMesh& tmesh, const VertexIndexMap& vertex_index)
    : Hinge_mesh(tmesh, faces(tmesh), static_cast<std::size_t>(num_vertices(tmesh)), vertex_index,
                 [](const std::array<Index, 4>&) { return true; })
  {
  }

  // The part of `tmesh` made of the triangles `face_range`, whose vertices `vertex_index` maps
  // to [0, number_of_vertices); its hinges are the edges between two of these triangles for
  // which `keep({a, b, c, d})` holds, a and b the edge's ends and c, d the opposite vertices.
  template <typename TriangleMesh, typename FaceRange, typename VertexIndexMap, typename Keep>
  Hinge_mesh(const TriangleMesh& tmesh, const FaceRange& face_range, std::size_t number_of_vertices,
             const VertexIndexMap& vertex_index, const Keep& keep)
    : number_of_vertices(number_of_vertices)
  {
    using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
    auto id = [&](auto v) { return static_cast<Index>(get(vertex_index, v)); };

    // Each triangle starts at its smallest vertex index, orientation kept.
    std::vector<std::pair<std::array<Index, 3>, face_descriptor> > sorted;
    for(face_descriptor f : face_range)
    {
      const auto h = halfedge(f, tmesh);
      std::array<Index, 3> t = {id(source(h, tmesh)), id(target(h, tmesh)),
                                      id(target(next(h, tmesh), tmesh))};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      sorted.emplace_back(t, f);
    }
    sort_by_vertex(sorted, number_of_vertices, [](const auto& t) { return t.first[0]; },
                   [](const auto& a, const auto& b) { return a.first < b.first; });
    constexpr Index no_face = ~Index(0);
    auto face_index = get(CGAL::dynamic_face_property_t<Index>(), tmesh);
    for(face_descriptor f : faces(tmesh))
      put(face_index, f, no_face);
    triangles.reserve(sorted.size());
    for(const auto& t : sorted)
    {
      put(face_index, t.second, static_cast<Index>(triangles.size()));
      triangles.push_back(t.first);
    }

    hinges.reserve(3 * sorted.size() / 2);
    for(const auto& t : sorted)
      for(auto h : halfedges_around_face(halfedge(t.second, tmesh), tmesh))
      {
        const auto o = opposite(h, tmesh);
        if(is_border(o, tmesh))
          continue;
        const Index f = get(face_index, t.second), g = get(face_index, face(o, tmesh));
        if(g == no_face || g < f)
          continue;
        const Index a = id(source(h, tmesh)), b = id(target(h, tmesh));
        if(keep(std::array<Index, 4>{a, b, id(target(next(h, tmesh), tmesh)), id(target(next(o, tmesh), tmesh))}))
          hinges.push_back(a < b ? Hinge{{a, b}, {f, g}} : Hinge{{b, a}, {g, f}});
      }
    sort_by_vertex(hinges, number_of_vertices, [](const Hinge& x) { return x.v[0]; },
                   [](const Hinge& x, const Hinge& y) { return x.v < y.v; });
  }
};

// A triangle's normal scaled by twice its area, and its centroid, at the points X.
inline Eigen::Vector3d area_normal(const Points& X, const std::array<Index, 3>& t)
{
  return (point(X, t[1]) - point(X, t[0])).cross(point(X, t[2]) - point(X, t[0]));
}

inline Eigen::Vector3d area_normal(const Hinge_mesh& mesh, const Points& X, std::size_t f)
{
  return area_normal(X, mesh.triangles[f]);
}

// The sine of a triangle's smallest angle, which lies between its two longer sides: the norm of
// their cross product over the product of their lengths (0 for a triangle of no area). The sides
// are first divided by their largest coordinate, so that no square underflows or overflows.
inline double smallest_angle_sine(const Points& X, const std::array<Index, 3>& t)
{
  std::array<Eigen::Vector3d, 3> sides = {Eigen::Vector3d(point(X, t[1]) - point(X, t[0])),
                                          Eigen::Vector3d(point(X, t[2]) - point(X, t[1])),
                                          Eigen::Vector3d(point(X, t[0]) - point(X, t[2]))};
  const double largest = (std::max)({sides[0].cwiseAbs().maxCoeff(), sides[1].cwiseAbs().maxCoeff(),
                                      sides[2].cwiseAbs().maxCoeff()});
  if(!(largest > 0))
    return 0.;
  for(Eigen::Vector3d& side : sides)
    side /= largest;
  std::sort(sides.begin(), sides.end(),
            [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.squaredNorm() < b.squaredNorm(); });
  return sides[1].cross(sides[2]).norm() / (sides[1].norm() * sides[2].norm());
}

inline Eigen::Vector3d centroid(const Hinge_mesh& mesh, const Points& X, std::size_t f)
{
  const auto& t = mesh.triangles[f];
  return (point(X, t[0]) + point(X, t[1]) + point(X, t[2])) / 3;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_HINGE_MESH_H
