// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a polygon soup (points and faces as lists of point indices, as read from a file or given
// as arrays) must be for CGAL's polygon_soup_to_polygon_mesh() to make a halfedge mesh of it:
// faces of three or more distinct existing points, as is_polygon_soup_a_polygon_mesh() demands
// (edges of at most two faces, consistently oriented, vertices of one fan), in 32-bit indices.
// A soup with a defect of these cannot become the mesh on which constrained_fairing() would
// name it, so it is named here, with the first face or vertex concerned, in the words of
// mesh_error() (Input_check.h). Every other defect, an empty mesh or one without faces among
// them, is left to constrained_fairing(). The sorts are counting sorts by vertex, so that the
// check costs little beside the fairing of a large mesh.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input_check.h>

#include <algorithm>
#include <limits>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// `polygons` is a random access range of random access ranges of point indices, each polygon
// listing its corners in order; `number_of_points` is the number of points they index.
template <typename PolygonRange>
Input_error polygon_soup_error(std::size_t number_of_points, const PolygonRange& polygons)
{
  using D = Constrained_fairing_defect;
  const std::size_t m = static_cast<std::size_t>(std::size(polygons));

  // The corners, numbered face by face; corner_start[f] is the first corner of face f.
  std::vector<std::size_t> corner_start(m + 1, 0);
  for(std::size_t f = 0; f < m; ++f)
  {
    const auto& polygon = polygons[f];
    const std::size_t k = static_cast<std::size_t>(std::size(polygon));
    if(k < 3)
      return {D::INVALID_FACE, "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices"};
    for(std::size_t c = 0; c < k; ++c)
    {
      const std::size_t v = static_cast<std::size_t>(polygon[c]);
      if(v >= number_of_points)
        return {D::INVALID_FACE, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                   ", but there are " + std::to_string(number_of_points) + " vertices"};
      for(std::size_t d = 0; d < c; ++d)
        if(static_cast<std::size_t>(polygon[d]) == v)
          return {D::INVALID_FACE, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " twice"};
    }
    corner_start[f + 1] = corner_start[f] + k;
  }
  // The arrays below, like the solver's (Points.h), number the vertices and corners in 32 bits.
  if(number_of_points > (std::numeric_limits<Index>::max)() || corner_start[m] >= (std::numeric_limits<Index>::max)())
    return {D::MESH_TOO_LARGE, "the mesh is too large: at most " + std::to_string((std::numeric_limits<Index>::max)()) +
                                 " vertices and face corners"};

  // Each corner's vertex, and the next corner around its face: the loops below run over them.
  const std::size_t corners = corner_start[m];
  std::vector<Index> corner_vertex(corners), next_corner(corners);
  for(std::size_t f = 0; f < m; ++f)
  {
    const auto& polygon = polygons[f];
    for(std::size_t c = corner_start[f]; c < corner_start[f + 1]; ++c)
    {
      corner_vertex[c] = static_cast<Index>(polygon[c - corner_start[f]]);
      next_corner[c] = static_cast<Index>(c + 1 < corner_start[f + 1] ? c + 1 : corner_start[f]);
    }
  }
  // The face of corner c, for messages.
  const auto face_of = [&](std::size_t c) {
    return std::size_t(std::upper_bound(corner_start.begin(), corner_start.end(), c) - corner_start.begin()) - 1;
  };

  // The sides of the faces, each named by the corner at its source, grouped by their smaller
  // vertex as in a counting sort and then sorted by (larger vertex, corner), which sorts them
  // by face too since the corners are numbered face by face.
  struct Side
  {
    Index b, corner;
  };
  std::vector<Index> start(number_of_points + 1, 0);
  for(std::size_t c = 0; c < corners; ++c)
    ++start[(std::min)(corner_vertex[c], corner_vertex[next_corner[c]]) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Side> sides(corners);
  {
    std::vector<Index> next(start.begin(), start.end() - 1);
    for(std::size_t c = 0; c < corners; ++c)
    {
      const Index s = corner_vertex[c], t = corner_vertex[next_corner[c]];
      sides[next[(std::min)(s, t)]++] = Side{(std::max)(s, t), static_cast<Index>(c)};
    }
  }
  for(std::size_t v = 0; v < number_of_points; ++v)
    std::sort(sides.begin() + std::ptrdiff_t(start[v]), sides.begin() + std::ptrdiff_t(start[v + 1]),
              [](const Side& x, const Side& y) { return x.b != y.b ? x.b < y.b : x.corner < y.corner; });

  // The corners around each vertex that are joined across an interior edge belong to one fan:
  // a union-find over the corners.
  std::vector<Index> parent(corners);
  std::iota(parent.begin(), parent.end(), Index(0));
  const auto root = [&parent](Index c) {
    while(parent[c] != c)
      c = parent[c] = parent[parent[c]];
    return c;
  };
  const auto join = [&](Index c, Index d) { parent[root(c)] = root(d); };

  for(std::size_t v = 0; v < number_of_points; ++v)
    for(std::size_t i = start[v], j = start[v]; i < start[v + 1]; i = j)
    {
      while(j < start[v + 1] && sides[j].b == sides[i].b)
        ++j;
      const Side& x = sides[i];
      if(j - i > 2)
        return {D::NON_MANIFOLD_EDGE, "the edge between vertices " + std::to_string(v) + " and " +
                                        std::to_string(x.b) + " has " + std::to_string(j - i) +
                                        " faces (a non-manifold edge)"};
      if(j - i < 2)
        continue;
      const Side& y = sides[i + 1];
      const Index source = corner_vertex[x.corner];
      if(source == corner_vertex[y.corner])
        return {D::INCONSISTENT_ORIENTATION,
                "faces " + std::to_string(face_of(x.corner)) + " and " + std::to_string(face_of(y.corner)) +
                  " are oriented inconsistently: both run from vertex " + std::to_string(source) + " to vertex " +
                  std::to_string(source == v ? x.b : v)};
      // x runs s -> t and y runs t -> s: x's source corner meets y's target corner, and so on.
      join(x.corner, next_corner[y.corner]);
      join(next_corner[x.corner], y.corner);
    }

  // A vertex whose corners are in more than one set is non-manifold; the smallest is named.
  std::vector<Index> fan(number_of_points, static_cast<Index>(corners)); // a corner's root, `corners` for none yet
  std::size_t first = number_of_points;
  for(std::size_t c = 0; c < corners; ++c)
  {
    const Index v = corner_vertex[c], r = root(static_cast<Index>(c));
    if(fan[v] == corners)
      fan[v] = r;
    else if(fan[v] != r)
      first = (std::min)(first, std::size_t(v));
  }
  if(first < number_of_points)
    return {D::NON_MANIFOLD_VERTEX, "vertex " + std::to_string(first) + " is non-manifold: its faces form more than one fan"};
  return {};
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H
