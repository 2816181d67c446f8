// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a polygon soup (points and faces as lists of point indices, as read from a file or given
// as arrays) must be for CGAL's polygon_soup_to_polygon_mesh() to make a halfedge mesh of it:
// faces of three or more distinct existing points, as is_polygon_soup_a_polygon_mesh() demands
// (edges of at most two faces, consistently oriented, vertices of one fan), in 32-bit indices.
// A soup with a defect of these cannot become the mesh on which constrained_fairing() would
// name it, so it is named here, with the first face or vertex concerned, by the library's own
// words for it (Input_defects.h). Every other defect, an empty mesh or one without faces among
// them, is left to constrained_fairing(). The sides of the faces are grouped by vertex with the
// library's counting sort (Rows_by_vertex.h), so that the check costs little beside the fairing
// of a large mesh.

#ifndef CONSTRAINED_FAIRING_FRONT_END_POLYGON_SOUP_CHECK_H
#define CONSTRAINED_FAIRING_FRONT_END_POLYGON_SOUP_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Face_corners.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Input/Input_defects.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <algorithm>
#include <limits>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace Constrained_fairing_front_end {

using CGAL::Polygon_mesh_processing::internal::Constrained_fairing::Index;
using CGAL::Polygon_mesh_processing::internal::Constrained_fairing::Input_error;

// `polygons` is a random access range of random access ranges of point indices, each polygon
// listing its corners in order; `number_of_points` is the number of points they index.
template <typename PolygonRange>
Input_error polygon_soup_error(std::size_t number_of_points, const PolygonRange& polygons)
{
  namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
  const std::size_t m = static_cast<std::size_t>(std::size(polygons));

  // The corners, numbered face by face; corner_start[f] is the first corner of face f.
  std::vector<std::size_t> corner_start(m + 1, 0);
  for(std::size_t f = 0; f < m; ++f)
  {
    const auto& polygon = polygons[f];
    const std::size_t k = static_cast<std::size_t>(std::size(polygon));
    if(k < 3)
      return CF::too_few_corners_error(f, k);
    if(Input_error error = CF::face_corner_error(f, polygon, number_of_points))
      return error;
    corner_start[f + 1] = corner_start[f] + k;
  }
  // The arrays below, like the solver's (Points.h), number the vertices and corners in 32 bits.
  if(number_of_points > (std::numeric_limits<Index>::max)() || corner_start[m] >= (std::numeric_limits<Index>::max)())
    return CF::mesh_too_large_error((std::numeric_limits<Index>::max)(), CF::Hinge_mesh::max_faces);

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
  // vertex and sorted by (larger vertex, corner), which sorts them by face too since the corners
  // are numbered face by face.
  struct Side
  {
    Index b, corner;
  };
  CF::Rows_by_vertex<Side> sides(number_of_points, [&](const auto& add) {
    for(std::size_t c = 0; c < corners; ++c)
    {
      const Index s = corner_vertex[c], t = corner_vertex[next_corner[c]];
      add((std::min)(s, t), Side{(std::max)(s, t), static_cast<Index>(c)});
    }
  });
  sides.sort_rows([](const Side& x, const Side& y) { return x.b != y.b ? x.b < y.b : x.corner < y.corner; });

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

  const std::vector<Side>& side = sides.items;
  for(std::size_t v = 0; v < number_of_points; ++v)
    for(std::size_t i = sides.first[v], j = sides.first[v]; i < sides.first[v + 1]; i = j)
    {
      while(j < sides.first[v + 1] && side[j].b == side[i].b)
        ++j;
      const Side& x = side[i];
      if(j - i > 2)
        return CF::crowded_edge_error(v, x.b, j - i);
      if(j - i < 2)
        continue;
      const Side& y = side[i + 1];
      const Index source = corner_vertex[x.corner];
      if(source == corner_vertex[y.corner])
        return CF::inconsistent_orientation_error(face_of(x.corner), face_of(y.corner), source, source == v ? x.b : v);
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
    return CF::non_manifold_vertex_error(first);
  return {};
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_POLYGON_SOUP_CHECK_H
