// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a polygon soup (points and faces as lists of point indices, as read from a file or given
// as arrays) must be for CGAL's polygon_soup_to_polygon_mesh() to make a halfedge mesh of it:
// faces of three or more distinct existing points, as is_polygon_soup_a_polygon_mesh() demands
// (edges of at most two faces, consistently oriented, vertices of one fan), in 32-bit indices.
// A soup with a defect of these cannot become the mesh on which constrained_fairing() would
// name it, so it is named here, with the first face or vertex concerned, in the words of
// Input_defects.h. Every other defect, an empty mesh or one without faces among them, is left
// to the mesh's own check. The sides of the faces are grouped by vertex with the counting sort
// of Rows_by_vertex.h, so that the check costs little beside the fairing of a large mesh.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Face_corners.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The corners of a soup's faces, numbered face by face: corner_start[f] is the first corner of
// face f; each corner's vertex, and the next corner around its face.
struct Soup_corners
{
  std::vector<std::size_t> corner_start;
  std::vector<Index> corner_vertex, next_corner;

  std::size_t size() const { return corner_vertex.size(); }

  // The face of corner c, for messages.
  std::size_t face_of(std::size_t c) const
  {
    return std::size_t(std::upper_bound(corner_start.begin(), corner_start.end(), c) - corner_start.begin()) - 1;
  }
};

// The first face with fewer than three corners or a corner that is no point of `n` or is
// listed twice, or a soup too large for 32-bit indices; otherwise `corners` gets its corners.
template <typename PolygonRange>
Input_error soup_corner_error(std::size_t n, const PolygonRange& polygons, Soup_corners& corners)
{
  const std::size_t m = static_cast<std::size_t>(std::size(polygons));
  std::vector<std::size_t>& start = corners.corner_start;
  start.assign(m + 1, 0);
  for(std::size_t f = 0; f < m; ++f)
  {
    const std::size_t k = static_cast<std::size_t>(std::size(polygons[f]));
    if(k < 3)
      return too_few_corners_error(f, k);
    if(Input_error error = face_corner_error(f, polygons[f], n))
      return error;
    start[f + 1] = start[f] + k;
  }
  // The arrays below, like the solver's (Points.h), number the vertices and corners in 32 bits.
  if(n > (std::numeric_limits<Index>::max)() || start[m] >= (std::numeric_limits<Index>::max)())
    return mesh_too_large_error((std::numeric_limits<Index>::max)(), Hinge_mesh::max_faces);
  corners.corner_vertex.resize(start[m]);
  corners.next_corner.resize(start[m]);
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t c = start[f]; c < start[f + 1]; ++c)
    {
      corners.corner_vertex[c] = static_cast<Index>(polygons[f][c - start[f]]);
      corners.next_corner[c] = static_cast<Index>(c + 1 < start[f + 1] ? c + 1 : start[f]);
    }
  return {};
}

// The corners around each vertex that are joined across an interior edge belong to one fan:
// a union-find over the corners.
struct Corner_fans
{
  std::vector<Index> parent;

  explicit Corner_fans(std::size_t corners) : parent(corners) { std::iota(parent.begin(), parent.end(), Index(0)); }

  Index root(Index c)
  {
    while(parent[c] != c)
      c = parent[c] = parent[parent[c]];
    return c;
  }

  void join(Index c, Index d) { parent[root(c)] = root(d); }
};

// The first edge of more than two faces or of two faces running the same way along it; the
// corners across each other edge of two faces joined in `fans`.
inline Input_error soup_edge_error(std::size_t n, const Soup_corners& corners, Corner_fans& fans)
{
  // The sides of the faces, each named by the corner at its source, grouped by their smaller
  // vertex and sorted by (larger vertex, corner), which sorts them by face too since the corners
  // are numbered face by face.
  struct Side
  {
    Index b, corner;
  };
  const std::vector<Index>& vertex = corners.corner_vertex;
  const std::vector<Index>& next = corners.next_corner;
  Rows_by_vertex<Side> sides(n, [&](const auto& add) {
    for(std::size_t c = 0; c < corners.size(); ++c)
    {
      const Index s = vertex[c], t = vertex[next[c]];
      add((std::min)(s, t), Side{(std::max)(s, t), static_cast<Index>(c)});
    }
  });
  sides.sort_rows([](const Side& x, const Side& y) { return x.b != y.b ? x.b < y.b : x.corner < y.corner; });
  const std::vector<Side>& side = sides.items;
  for(std::size_t v = 0; v < n; ++v)
    for(std::size_t i = sides.first[v], j = sides.first[v]; i < sides.first[v + 1]; i = j)
    {
      while(j < sides.first[v + 1] && side[j].b == side[i].b)
        ++j;
      const Side& x = side[i];
      if(j - i > 2)
        return crowded_edge_error(v, x.b, j - i);
      if(j - i < 2)
        continue;
      const Side& y = side[i + 1];
      const Index source = vertex[x.corner];
      if(source == vertex[y.corner])
        return inconsistent_orientation_error(corners.face_of(x.corner), corners.face_of(y.corner), source,
                                              source == v ? x.b : v);
      // x runs s -> t and y runs t -> s: x's source corner meets y's target corner, and so on.
      fans.join(x.corner, next[y.corner]);
      fans.join(next[x.corner], y.corner);
    }
  return {};
}

// A vertex whose corners are in more than one fan is non-manifold; the smallest is named.
inline Input_error soup_vertex_error(std::size_t n, const Soup_corners& corners, Corner_fans& fans)
{
  const Index none = static_cast<Index>(corners.size());
  std::vector<Index> fan(n, none); // the root of a vertex's first corner
  std::size_t first = n;
  for(std::size_t c = 0; c < corners.size(); ++c)
  {
    const Index v = corners.corner_vertex[c], r = fans.root(static_cast<Index>(c));
    if(fan[v] == none)
      fan[v] = r;
    else if(fan[v] != r)
      first = (std::min)(first, std::size_t(v));
  }
  if(first < n)
    return non_manifold_vertex_error(first);
  return {};
}

// The first defect that keeps `polygons`, a random access range of random access ranges of the
// indices of `n` points (any integer type), each polygon listing its corners in order, from
// becoming a halfedge mesh.
template <typename PolygonRange>
Input_error polygon_soup_error(std::size_t n, const PolygonRange& polygons)
{
  Soup_corners corners;
  if(Input_error error = soup_corner_error(n, polygons, corners))
    return error;
  Corner_fans fans(corners.size());
  if(Input_error error = soup_edge_error(n, corners, fans))
    return error;
  return soup_vertex_error(n, corners, fans);
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H
