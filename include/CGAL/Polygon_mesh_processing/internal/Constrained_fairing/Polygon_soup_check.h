// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input contract of constrained_fairing() for a polygon soup (points and faces as lists of
// point indices, as read from a file or given as arrays), checked before the soup is turned
// into a halfedge mesh: CGAL's polygon_soup_to_polygon_mesh() requires a soup that
// is_polygon_soup_a_polygon_mesh() accepts, and this check accepts no other, but names the
// defect, with the first face or vertex concerned, in the words of mesh_error() (Input_check.h).
// Its sorts are counting sorts by vertex, so that it costs little beside the fairing of a large
// mesh.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POLYGON_SOUP_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input_check.h>

#include <algorithm>
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
  if(number_of_points == 0)
    return {D::EMPTY_MESH, "the mesh is empty"};
  if(m == 0)
    return {D::NO_FACES, "the mesh has no faces"};

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
  const std::size_t corners = corner_start[m];
  const auto vertex_at = [&](std::size_t f, std::size_t c) {
    const auto& polygon = polygons[f];
    return static_cast<std::size_t>(polygon[c % static_cast<std::size_t>(std::size(polygon))]);
  };

  // The sides of the faces, as (smaller vertex, larger vertex, face, corner of the side's
  // source), sorted by (smaller, larger, face): placed by the smaller vertex as in a counting
  // sort, then each vertex's few sides sorted.
  struct Side
  {
    std::size_t a, b, face, corner;
  };
  std::vector<std::size_t> start(number_of_points + 1, 0);
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t c = 0; c < corner_start[f + 1] - corner_start[f]; ++c)
      ++start[(std::min)(vertex_at(f, c), vertex_at(f, c + 1)) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Side> sides(corners);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for(std::size_t f = 0; f < m; ++f)
      for(std::size_t c = 0; c < corner_start[f + 1] - corner_start[f]; ++c)
      {
        const std::size_t s = vertex_at(f, c), t = vertex_at(f, c + 1);
        sides[next[(std::min)(s, t)]++] = Side{(std::min)(s, t), (std::max)(s, t), f, corner_start[f] + c};
      }
  }
  for(std::size_t v = 0; v < number_of_points; ++v)
    std::sort(sides.begin() + std::ptrdiff_t(start[v]), sides.begin() + std::ptrdiff_t(start[v + 1]),
              [](const Side& x, const Side& y) { return x.b != y.b ? x.b < y.b : x.face < y.face; });

  // The corners around each vertex that are joined across an interior edge belong to one fan:
  // a union-find over the corners, each corner named by its index.
  std::vector<std::size_t> parent(corners);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&parent](std::size_t c) {
    while(parent[c] != c)
      c = parent[c] = parent[parent[c]];
    return c;
  };
  const auto join = [&](std::size_t c, std::size_t d) { parent[root(c)] = root(d); };
  // The corner after corner `c` in its face, `c` being corner `c - corner_start[f]` of face f.
  const auto next_corner = [&](std::size_t f, std::size_t c) { return c + 1 == corner_start[f + 1] ? corner_start[f] : c + 1; };

  for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    while(j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b)
      ++j;
    const Side& x = sides[i];
    if(j - i > 2)
      return {D::NON_MANIFOLD_EDGE, "the edge between vertices " + std::to_string(x.a) + " and " + std::to_string(x.b) +
                                      " has " + std::to_string(j - i) + " faces (a non-manifold edge)"};
    if(j - i < 2)
      continue;
    const Side& y = sides[i + 1];
    const std::size_t x_source = vertex_at(x.face, x.corner - corner_start[x.face]);
    const std::size_t y_source = vertex_at(y.face, y.corner - corner_start[y.face]);
    if(x_source == y_source)
      return {D::INCONSISTENT_ORIENTATION,
              "faces " + std::to_string(x.face) + " and " + std::to_string(y.face) +
                " are oriented inconsistently: both run from vertex " + std::to_string(x_source) + " to vertex " +
                std::to_string(x_source == x.a ? x.b : x.a)};
    // x runs s -> t and y runs t -> s: x's source corner meets y's target corner, and so on.
    join(x.corner, next_corner(y.face, y.corner));
    join(next_corner(x.face, x.corner), y.corner);
  }

  // A vertex whose corners are in more than one set is non-manifold; the smallest is named.
  std::vector<std::size_t> fan(number_of_points, corners); // a corner's root, `corners` for none yet
  std::size_t first = number_of_points;
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t c = corner_start[f]; c < corner_start[f + 1]; ++c)
    {
      const std::size_t v = vertex_at(f, c - corner_start[f]), r = root(c);
      if(fan[v] == corners)
        fan[v] = r;
      else if(fan[v] != r)
        first = (std::min)(first, v);
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
