// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Machined parts whose sharp edges are mostly moderate (40 to 60 degrees), made here so that a
// benchmark of crease detection does not rest on CAD parts whose edges are right angles:
//
// - `chamfered_block`: a box whose twelve edges are cut at 45 degrees (45-degree edges between
//   its faces and the chamfers, 35-degree ones round the corner triangles);
// - `gear`: a spur gear of trapezoidal teeth, extruded (50-degree edges at the teeth's roots and
//   tips, right angles round its two faces);
// - `stepped_shaft`: a shaft of two diameters turned about its axis, each rim chamfered at 45
//   degrees (45-degree rings, one 90-degree ring at the inner step);
// - `pyramid_boss`: a square plate with a pyramid on it (short creases of 45 and 60 degrees, a
//   part whose sharp edges are few and short).
//
// Each is a coarse tessellation, as CAD parts come; the benchmark remeshes it.

#ifndef CONSTRAINED_FAIRING_BENCHMARK_MADE_PARTS_H
#define CONSTRAINED_FAIRING_BENCHMARK_MADE_PARTS_H

#include "benchmark_support.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace benchmark {

// The convex polygon `corners` (indices into `points`, in cyclic order) fanned into `mesh`,
// facing away from the origin, which the solid holds.
inline void add_convex_polygon(Mesh& mesh, const std::vector<Point>& points, std::vector<std::size_t> corners)
{
  const Point& p0 = points[corners[0]];
  const auto normal = CGAL::cross_product(points[corners[1]] - p0, points[corners[2]] - p0);
  if(normal * (p0 - CGAL::ORIGIN) < 0)
    std::reverse(corners.begin(), corners.end());
  for(std::size_t k = 1; k + 1 < corners.size(); ++k)
    mesh.add_face(Mesh::Vertex_index(Mesh::size_type(corners[0])), Mesh::Vertex_index(Mesh::size_type(corners[k])),
                  Mesh::Vertex_index(Mesh::size_type(corners[k + 1])));
}

// Built face by face rather than as a convex hull, whose triangulation of the coplanar faces,
// and the remeshing after it, changed from one run to the next.
inline Mesh chamfered_block()
{
  const double half[3] = {2.0, 1.5, 1.0}, cut = 0.3;
  // the corners of each box face's part that the chamfers leave: point 8 axis + 4 s0 + 2 s1 + s2
  // (s_k = 1 for the positive side) lies on the face across `axis` on the side s_axis
  std::vector<Point> points;
  for(int axis = 0; axis < 3; ++axis)
    for(int s0 : {-1, 1})
      for(int s1 : {-1, 1})
        for(int s2 : {-1, 1})
        {
          const int s[3] = {s0, s1, s2};
          double c[3];
          for(int k = 0; k < 3; ++k)
            c[k] = s[k] * (k == axis ? half[k] : half[k] - cut);
          points.emplace_back(c[0], c[1], c[2]);
        }
  const auto index = [](int axis, const int side[3]) {
    return std::size_t(8 * axis + 4 * side[0] + 2 * side[1] + side[2]);
  };
  Mesh mesh;
  for(const Point& p : points)
    mesh.add_vertex(p);
  for(int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for(int sa = 0; sa < 2; ++sa)
    {
      // the box face across a
      std::vector<std::size_t> face;
      for(const auto& [sb, sc] : {std::pair<int, int>{0, 0}, {1, 0}, {1, 1}, {0, 1}})
      {
        int side[3];
        side[a] = sa, side[b] = sb, side[c] = sc;
        face.push_back(index(a, side));
      }
      add_convex_polygon(mesh, points, face);
      // the chamfers between it and the faces across b, at both ends of c
      for(int sb = 0; sb < 2; ++sb)
      {
        std::vector<std::size_t> chamfer;
        for(const auto& [axis, sc] : {std::pair<int, int>{a, 0}, {a, 1}, {b, 1}, {b, 0}})
        {
          int side[3];
          side[a] = sa, side[b] = sb, side[c] = sc;
          chamfer.push_back(index(axis, side));
        }
        add_convex_polygon(mesh, points, chamfer);
      }
    }
  }
  // the corner triangles
  for(int octant = 0; octant < 8; ++octant)
  {
    const int side[3] = {octant >> 2 & 1, octant >> 1 & 1, octant & 1};
    add_convex_polygon(mesh, points, {index(0, side), index(1, side), index(2, side)});
  }
  return mesh;
}

// The closed prism over `outline` (counter-clockwise, star-shaped about the origin) from z = 0
// to z = `height`, its two faces fanned about their centres.
inline Mesh extruded(const std::vector<std::pair<double, double> >& outline, double height)
{
  Mesh mesh;
  const std::size_t n = outline.size();
  std::vector<Mesh::Vertex_index> bottom, top;
  for(const auto& p : outline)
  {
    bottom.push_back(mesh.add_vertex(Point(p.first, p.second, 0)));
    top.push_back(mesh.add_vertex(Point(p.first, p.second, height)));
  }
  const auto low = mesh.add_vertex(Point(0, 0, 0)), high = mesh.add_vertex(Point(0, 0, height));
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    mesh.add_face(bottom[i], bottom[j], top[j]);
    mesh.add_face(bottom[i], top[j], top[i]);
    mesh.add_face(low, bottom[j], bottom[i]);
    mesh.add_face(high, top[i], top[j]);
  }
  return mesh;
}

inline Mesh gear()
{
  const int teeth = 14;
  const double root = 1.0, tip = 1.25, pi = std::acos(-1.);
  // a tooth's flanks lean 40 degrees off the radial line, so that the outline turns by 50
  // degrees at each root and tip corner
  const double pitch = 2 * pi / teeth, lean = 40 * pi / 180;
  const double flank = (tip - root) * std::tan(lean) / root; // the angle a flank spans, about
  const double tip_width = 0.25 * pitch;
  std::vector<std::pair<double, double> > outline;
  for(int t = 0; t < teeth; ++t)
  {
    const double a = t * pitch;
    const double angles[4] = {a, a + flank, a + flank + tip_width, a + 2 * flank + tip_width};
    const double radii[4] = {root, tip, tip, root};
    for(int k = 0; k < 4; ++k)
      outline.emplace_back(radii[k] * std::cos(angles[k]), radii[k] * std::sin(angles[k]));
    // the root between two teeth, an arc
    const double next = a + pitch, last = angles[3];
    for(int k = 1; k < 3; ++k)
    {
      const double b = last + (next - last) * k / 3;
      outline.emplace_back(root * std::cos(b), root * std::sin(b));
    }
  }
  return extruded(outline, 0.8);
}

// The closed surface turned from the profile (r, z), r = 0 at both ends, in `segments` steps.
inline Mesh turned(const std::vector<std::pair<double, double> >& profile, int segments)
{
  Mesh mesh;
  const double pi = std::acos(-1.);
  const std::size_t n = profile.size();
  const auto bottom = mesh.add_vertex(Point(0, 0, profile.front().second));
  const auto top = mesh.add_vertex(Point(0, 0, profile.back().second));
  std::vector<std::vector<Mesh::Vertex_index> > ring(n);
  for(std::size_t i = 1; i + 1 < n; ++i)
    for(int s = 0; s < segments; ++s)
    {
      const double a = 2 * pi * s / segments, r = profile[i].first;
      ring[i].push_back(mesh.add_vertex(Point(r * std::cos(a), r * std::sin(a), profile[i].second)));
    }
  for(int s = 0; s < segments; ++s)
  {
    const int t = (s + 1) % segments;
    mesh.add_face(bottom, ring[1][t], ring[1][s]);
    for(std::size_t i = 1; i + 2 < n; ++i)
    {
      mesh.add_face(ring[i][s], ring[i][t], ring[i + 1][t]);
      mesh.add_face(ring[i][s], ring[i + 1][t], ring[i + 1][s]);
    }
    mesh.add_face(top, ring[n - 2][s], ring[n - 2][t]);
  }
  return mesh;
}

inline Mesh stepped_shaft()
{
  return turned({{0, 0}, {0.9, 0}, {1.0, 0.1}, {1.0, 1.5}, {0.9, 1.6}, {0.7, 1.6}, {0.7, 3.0}, {0.6, 3.1}, {0, 3.1}},
                72);
}

inline Mesh pyramid_boss()
{
  // a plate of 4 x 4 x 0.5 and, on its top, a pyramid of base 1 and height 0.5 (45-degree
  // slopes: 45 degrees round its base, 60 along its ridges)
  Mesh mesh;
  std::vector<Point> plate = {{-2, -2, -0.5}, {2, -2, -0.5}, {2, 2, -0.5}, {-2, 2, -0.5},
                              {-2, -2, 0},    {2, -2, 0},    {2, 2, 0},    {-2, 2, 0}};
  std::vector<Mesh::Vertex_index> v;
  for(const Point& p : plate)
    v.push_back(mesh.add_vertex(p));
  const auto b0 = mesh.add_vertex(Point(-0.5, -0.5, 0)), b1 = mesh.add_vertex(Point(0.5, -0.5, 0)),
             b2 = mesh.add_vertex(Point(0.5, 0.5, 0)), b3 = mesh.add_vertex(Point(-0.5, 0.5, 0)),
             apex = mesh.add_vertex(Point(0, 0, 0.5));
  mesh.add_face(v[0], v[2], v[1]);
  mesh.add_face(v[0], v[3], v[2]);
  for(int i = 0; i < 4; ++i)
  {
    const int j = (i + 1) % 4;
    mesh.add_face(v[i], v[j], v[4 + j]);
    mesh.add_face(v[i], v[4 + j], v[4 + i]);
  }
  // the top face, a square ring round the pyramid's base
  const Mesh::Vertex_index base[4] = {b0, b1, b2, b3};
  for(int i = 0; i < 4; ++i)
  {
    const int j = (i + 1) % 4;
    mesh.add_face(v[4 + i], v[4 + j], base[j]);
    mesh.add_face(v[4 + i], base[j], base[i]);
    mesh.add_face(base[i], base[j], apex);
  }
  return mesh;
}

// The made parts by name, and whether `name` is one.
inline bool made_part(const std::string& name, Mesh& mesh)
{
  if(name == "chamfered-block")
    mesh = chamfered_block();
  else if(name == "gear")
    mesh = gear();
  else if(name == "stepped-shaft")
    mesh = stepped_shaft();
  else if(name == "pyramid-boss")
    mesh = pyramid_boss();
  else
    return false;
  return true;
}

} // namespace benchmark

#endif // CONSTRAINED_FAIRING_BENCHMARK_MADE_PARTS_H
