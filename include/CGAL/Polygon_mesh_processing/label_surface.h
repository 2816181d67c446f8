// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PMP_LABEL_SURFACE_H
#define CGAL_PMP_LABEL_SURFACE_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <utility>
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
  using Vector = std::array<double, 3>;

  // The label's triangles, oriented outward.
  std::vector<std::array<std::size_t, 3> > own;
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const auto& sides = face_labels[f];
    if(sides[0] != label && sides[1] != label)
      continue;
    const std::size_t a = std::size_t(triangles[f][0]), b = std::size_t(triangles[f][1]),
                      c = std::size_t(triangles[f][2]);
    own.push_back(sides[0] == label ? std::array<std::size_t, 3>{a, b, c} : std::array<std::size_t, 3>{a, c, b});
  }
  const std::size_t m = own.size();

  // The sides of the triangles, grouped by edge.
  struct Side
  {
    std::size_t a, b; // the edge's ends, a < b
    std::size_t face;
    int corner; // the side runs from own[face][corner] to the next corner
  };
  std::vector<Side> sides;
  sides.reserve(3 * m);
  for(std::size_t f = 0; f < m; ++f)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t s = own[f][std::size_t(c)], t = own[f][std::size_t((c + 1) % 3)];
      sides.push_back({(std::min)(s, t), (std::max)(s, t), f, c});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.face < y.face;
  });
  const auto runs_forward = [&](const Side& x) { return own[x.face][std::size_t(x.corner)] == x.a; };
  const auto position = [&](std::size_t p) {
    return Vector{CGAL::to_double(points[p].x()), CGAL::to_double(points[p].y()), CGAL::to_double(points[p].z())};
  };

  // The edges of two sides, joined if they run opposite ways; and the edges where sheets meet,
  // their sides sorted by the angle of their third point around the edge, counterclockwise seen
  // from its end b.
  std::vector<std::size_t> plain;
  std::vector<std::vector<std::size_t> > crowded;
  for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    while(j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b)
      ++j;
    if(j - i == 2)
    {
      if(runs_forward(sides[i]) != runs_forward(sides[i + 1]))
        plain.push_back(i);
      continue;
    }
    const Vector A = position(sides[i].a), B = position(sides[i].b);
    const Vector d = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    const auto cross = [](const Vector& x, const Vector& y) {
      return Vector{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    const auto dot = [](const Vector& x, const Vector& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    // A frame (e1, e2) of the plane normal to d, with e1 x e2 along d.
    const Vector helper = std::abs(d[0]) <= std::abs(d[1]) && std::abs(d[0]) <= std::abs(d[2]) ? Vector{1, 0, 0}
                          : std::abs(d[1]) <= std::abs(d[2])                                 ? Vector{0, 1, 0}
                                                                                             : Vector{0, 0, 1};
    const Vector e1 = cross(helper, d), e2 = cross(d, e1);
    std::vector<std::pair<double, std::size_t> > around;
    for(std::size_t k = i; k < j; ++k)
    {
      const Vector C = position(own[sides[k].face][std::size_t((sides[k].corner + 2) % 3)]);
      const Vector u = {C[0] - A[0], C[1] - A[1], C[2] - A[2]};
      around.emplace_back(std::atan2(dot(u, e2), dot(u, e1)), k);
    }
    std::sort(around.begin(), around.end());
    crowded.emplace_back();
    for(const auto& side : around)
      crowded.back().push_back(side.second);
  }

  // The corners (3 f + c) that are one vertex: those joined across the edges. Around an edge
  // where sheets meet, the region lies clockwise of a triangle that runs a -> b and
  // counterclockwise of one that runs b -> a; each of the latter is joined to the next triangle
  // counterclockwise, the other wall of the same wedge of the region (the sheets stay apart), or,
  // where that would join them anyway at both ends of the edge (the region goes around the edge),
  // to the next one clockwise, across a wedge of the outside (the sheets merge along the edge).
  std::vector<std::size_t> parent(3 * m);
  const auto root = [&parent](std::size_t c) {
    while(parent[c] != c)
      c = parent[c] = parent[parent[c]];
    return c;
  };
  // x's side c runs from corner 3 f + c to the next; y's runs the other way.
  const auto join = [&](const Side& x, const Side& y) {
    parent[root(3 * x.face + std::size_t(x.corner))] = root(3 * y.face + std::size_t((y.corner + 1) % 3));
    parent[root(3 * x.face + std::size_t((x.corner + 1) % 3))] = root(3 * y.face + std::size_t(y.corner));
  };
  // The pairs of sides joined around crowded edge e, by `across_outside[e]`.
  const auto pairs = [&](std::size_t e, bool across_outside, const auto& f) {
    const std::vector<std::size_t>& ring = crowded[e];
    for(std::size_t r = 0; r < ring.size(); ++r)
    {
      const Side& x = sides[ring[r]];
      const Side& y = sides[ring[(r + (across_outside ? ring.size() - 1 : 1)) % ring.size()]];
      if(!runs_forward(x) && runs_forward(y))
        f(x, y);
    }
  };
  std::vector<bool> across_outside(crowded.size(), false);
  for(std::size_t round = 0; round <= crowded.size(); ++round)
  {
    for(std::size_t c = 0; c < parent.size(); ++c)
      parent[c] = c;
    for(std::size_t i : plain)
      join(sides[i], sides[i + 1]);
    for(std::size_t e = 0; e < crowded.size(); ++e)
      pairs(e, across_outside[e], join);
    // An edge whose pairs end at the same two vertices is switched to the other pairing.
    bool switched = false;
    for(std::size_t e = 0; e < crowded.size(); ++e)
    {
      std::vector<std::array<std::size_t, 2> > ends;
      pairs(e, across_outside[e], [&](const Side& x, const Side&) {
        std::array<std::size_t, 2> v = {root(3 * x.face + std::size_t(x.corner)),
                                        root(3 * x.face + std::size_t((x.corner + 1) % 3))};
        std::sort(v.begin(), v.end());
        ends.push_back(v);
      });
      std::sort(ends.begin(), ends.end());
      if(std::adjacent_find(ends.begin(), ends.end()) != ends.end())
      {
        across_outside[e] = !across_outside[e];
        switched = true;
      }
    }
    if(!switched)
      break;
  }

  // One vertex per set of joined corners, numbered in the order of their first corner; its point
  // is the corners' point.
  constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> vertex_of_root(3 * m, none), origin;
  std::vector<Point> mesh_points;
  std::vector<std::array<std::size_t, 3> > faces(m);
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t c = 0; c < 3; ++c)
    {
      std::size_t& v = vertex_of_root[root(3 * f + c)];
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
