// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_LABEL_SURFACE_H
#define CGAL_PMP_LABEL_SURFACE_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Label_maps/Surface_corners.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
\ingroup PkgConstrainedFairingRef

\brief makes the closed surface of one label of a multi-label triangle soup, as
`label_surface_nets()` gives it, oriented outward.

The surface is made of the triangles whose `face_labels` name `label`, oriented so that their
normals point out of `label`'s region: a triangle whose normal points from the region of
`face_labels[f][0]` into that of `face_labels[f][1]` is kept as it is when `label` is the first,
and reversed when it is the second. Its points are copies of `points`, bit for bit, so the
surfaces of two labels share their interface exactly.

The soup of `label_surface_nets()` gives each label a manifold as it is (its points are shared
by no two sheets), except in the rare dual cells of three labels or more that its rule leaves
with one point. Where a label's triangles are not a manifold (such a cell, or a soup made
elsewhere), the surface is split there, so that `tmesh` is a manifold whose sheets touch at
copies of the shared points. Along an edge of more than two triangles, each triangle is joined to
its neighbour around the edge across the label's region (the triangles are sorted by angle
around the edge); at a point, the triangles joined across edges make one vertex, and each other
fan gets its own.

\tparam PointRange a random access range of points convertible to the point type of `tmesh`
\tparam TriangleRange a random access range of arrays of three point indices (any integer type)
\tparam LabelPairRange a random access range of `std::array<Label, 2>`, one per triangle
\tparam Label an integer type
\tparam PolygonMesh a model of `MutableFaceGraph`

\param points the points of the soup
\param triangles the triangles, as indices into `points`
\param face_labels the two labels of each triangle
\param label the label whose surface is made
\param tmesh the surface, appended to
\param vertex_points if not null, the index into `points` of each vertex added to `tmesh`, in
       the order `vertices(tmesh)` lists them after those `tmesh` had before

\return the number of triangles of the surface
*/
template <typename PointRange, typename TriangleRange, typename LabelPairRange, typename Label, typename PolygonMesh>
std::size_t label_surface(const PointRange& points, const TriangleRange& triangles,
                          const LabelPairRange& face_labels, const Label label, PolygonMesh& tmesh,
                          std::vector<std::size_t>* vertex_points = nullptr)
{
  using Point = typename std::iterator_traits<typename PointRange::const_iterator>::value_type;
  namespace Cf = internal::Constrained_fairing;
  const std::vector<Cf::Surface_triangle> own = Cf::outward_triangles(triangles, face_labels, label);
  const std::size_t m = own.size();
  Cf::Surface_corners corners(points, own);
  // One vertex per set of joined corners, numbered in the order of their first corner; its point
  // is the corners' point.
  constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> vertex_of_root(3 * m, none), origin;
  std::vector<Point> mesh_points;
  std::vector<std::array<std::size_t, 3> > faces(m);
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t c = 0; c < 3; ++c)
    {
      std::size_t& v = vertex_of_root[corners.root(3 * f + c)];
      if(v == none)
      {
        v = mesh_points.size();
        mesh_points.push_back(points[own[f][c]]);
        origin.push_back(own[f][c]);
      }
      faces[f][c] = v;
    }
  if(vertex_points)
    vertex_points->insert(vertex_points->end(), origin.begin(), origin.end());
  polygon_soup_to_polygon_mesh(mesh_points, faces, tmesh);
  return m;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_LABEL_SURFACE_H
