// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The corners of a label's triangles that are one vertex of its surface (label_surface()): the
// corners joined across the edges of two triangles that run opposite ways and, around an edge
// where sheets meet, across the wedges of the label's region or of the outside, so that each
// sheet is a manifold of its own.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SURFACE_CORNERS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SURFACE_CORNERS_H

#include <CGAL/number_utils.h>

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

using Surface_triangle = std::array<std::size_t, 3>;

// The triangles whose `face_labels` name `label`, oriented so that their normals point out of
// its region.
template <typename TriangleRange, typename LabelPairRange, typename Label>
std::vector<Surface_triangle> outward_triangles(const TriangleRange& triangles, const LabelPairRange& face_labels,
                                                const Label label)
{
  std::vector<Surface_triangle> own;
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const auto& sides = face_labels[f];
    if(sides[0] != label && sides[1] != label)
      continue;
    const std::size_t a = std::size_t(triangles[f][0]), b = std::size_t(triangles[f][1]),
                      c = std::size_t(triangles[f][2]);
    own.push_back(sides[0] == label ? Surface_triangle{a, b, c} : Surface_triangle{a, c, b});
  }
  return own;
}

// A side of a triangle, on the edge between points a < b.
struct Triangle_side
{
  std::size_t a, b;
  std::size_t face;
  int corner; // the side runs from own[face][corner] to the next corner
};

// The sides of the triangles `own`, grouped by edge, by triangle within.
inline std::vector<Triangle_side> sides_by_edge(const std::vector<Surface_triangle>& own)
{
  std::vector<Triangle_side> sides;
  sides.reserve(3 * own.size());
  for(std::size_t f = 0; f < own.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t s = own[f][std::size_t(c)], t = own[f][std::size_t((c + 1) % 3)];
      sides.push_back({(std::min)(s, t), (std::max)(s, t), f, c});
    }
  std::sort(sides.begin(), sides.end(), [](const Triangle_side& x, const Triangle_side& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.face < y.face;
  });
  return sides;
}

// The sides [i, j) of one edge, where sheets meet, sorted by the angle of their third point
// around the edge, counterclockwise seen from its end b.
template <typename PointRange>
std::vector<std::size_t> sides_around_edge(const PointRange& points, const std::vector<Surface_triangle>& own,
                                           const std::vector<Triangle_side>& sides, std::size_t i, std::size_t j)
{
  using Vector = std::array<double, 3>;
  const auto position = [&](std::size_t p) {
    return Vector{CGAL::to_double(points[p].x()), CGAL::to_double(points[p].y()), CGAL::to_double(points[p].z())};
  };
  const auto cross = [](const Vector& x, const Vector& y) {
    return Vector{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  const auto dot = [](const Vector& x, const Vector& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const Vector A = position(sides[i].a), B = position(sides[i].b);
  const Vector d = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
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
  std::vector<std::size_t> sorted;
  for(const auto& side : around)
    sorted.push_back(side.second);
  return sorted;
}

// Which corners (3 f + c) of the triangles `own` are one vertex: those joined across the edges.
// Around an edge where sheets meet, the region lies clockwise of a triangle that runs a -> b and
// counterclockwise of one that runs b -> a; each of the latter is joined to the next triangle
// counterclockwise, the other wall of the same wedge of the region (the sheets stay apart), or,
// where that would join them anyway at both ends of the edge (the region goes around the edge),
// to the next one clockwise, across a wedge of the outside (the sheets merge along the edge).
class Surface_corners
{
public:
  template <typename PointRange>
  Surface_corners(const PointRange& points, const std::vector<Surface_triangle>& own)
    : m_own(own), m_sides(sides_by_edge(own)), m_parent(3 * own.size())
  {
    // The edges of two sides, joined if they run opposite ways; and the crowded edges.
    for(std::size_t i = 0, j = 0; i < m_sides.size(); i = j)
    {
      while(j < m_sides.size() && m_sides[j].a == m_sides[i].a && m_sides[j].b == m_sides[i].b)
        ++j;
      if(j - i != 2)
        m_crowded.push_back(sides_around_edge(points, own, m_sides, i, j));
      else if(runs_forward(m_sides[i]) != runs_forward(m_sides[i + 1]))
        m_plain.push_back(i);
    }
    std::vector<bool> across_outside(m_crowded.size(), false);
    for(std::size_t round = 0; round <= m_crowded.size(); ++round)
      if(!join_all(across_outside))
        break;
  }

  // The corner that stands for the vertex of corner c.
  std::size_t root(std::size_t c)
  {
    while(m_parent[c] != c)
      c = m_parent[c] = m_parent[m_parent[c]];
    return c;
  }

private:
  bool runs_forward(const Triangle_side& x) const { return m_own[x.face][std::size_t(x.corner)] == x.a; }

  // x's side c runs from corner 3 f + c to the next; y's runs the other way.
  void join(const Triangle_side& x, const Triangle_side& y)
  {
    m_parent[root(3 * x.face + std::size_t(x.corner))] = root(3 * y.face + std::size_t((y.corner + 1) % 3));
    m_parent[root(3 * x.face + std::size_t((x.corner + 1) % 3))] = root(3 * y.face + std::size_t(y.corner));
  }

  // The pairs of sides joined around crowded edge e, across the outside or the region.
  template <typename F>
  void pairs(std::size_t e, bool across_outside, const F& f) const
  {
    const std::vector<std::size_t>& ring = m_crowded[e];
    for(std::size_t r = 0; r < ring.size(); ++r)
    {
      const Triangle_side& x = m_sides[ring[r]];
      const Triangle_side& y = m_sides[ring[(r + (across_outside ? ring.size() - 1 : 1)) % ring.size()]];
      if(!runs_forward(x) && runs_forward(y))
        f(x, y);
    }
  }

  // Joins the corners afresh; an edge whose pairs end at the same two vertices is then switched
  // to the other pairing. Whether one was.
  bool join_all(std::vector<bool>& across_outside)
  {
    for(std::size_t c = 0; c < m_parent.size(); ++c)
      m_parent[c] = c;
    for(std::size_t i : m_plain)
      join(m_sides[i], m_sides[i + 1]);
    for(std::size_t e = 0; e < m_crowded.size(); ++e)
      pairs(e, across_outside[e], [this](const Triangle_side& x, const Triangle_side& y) { join(x, y); });
    bool switched = false;
    for(std::size_t e = 0; e < m_crowded.size(); ++e)
    {
      std::vector<std::array<std::size_t, 2> > ends;
      pairs(e, across_outside[e], [&](const Triangle_side& x, const Triangle_side&) {
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
    return switched;
  }

  const std::vector<Surface_triangle>& m_own;
  std::vector<Triangle_side> m_sides;
  std::vector<std::size_t> m_plain;                  // the first side of each
  std::vector<std::vector<std::size_t> > m_crowded; // the sides of each, by angle
  std::vector<std::size_t> m_parent;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SURFACE_CORNERS_H
