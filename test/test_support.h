// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes with a known true surface, seeded noise and a check macro for the tests.

#ifndef CGAL_CONSTRAINED_FAIRING_TEST_SUPPORT_H
#define CGAL_CONSTRAINED_FAIRING_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

namespace test {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;

inline int failures = 0;

#define CHECK(condition)                                                                      \
  do                                                                                          \
  {                                                                                           \
    if(!(condition))                                                                          \
    {                                                                                         \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl; \
      ++test::failures;                                                                       \
    }                                                                                         \
  } while(false)

inline int report(const char* name)
{
  std::cout << name << ": " << (failures == 0 ? "passed" : "FAILED") << " (" << failures
            << " failed checks)" << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// The unit sphere, Loop subdivided from an icosahedron; 10 * 4^levels + 2 vertices.
template <typename PolygonMesh = Mesh>
PolygonMesh icosphere(unsigned int levels)
{
  PolygonMesh m;
  CGAL::make_icosahedron(m, Point(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(levels));
  for(auto v : vertices(m))
  {
    const Point p = get(CGAL::vertex_point, m, v);
    const Vector d = p - CGAL::ORIGIN;
    put(get(CGAL::vertex_point, m), v, CGAL::ORIGIN + d / std::sqrt(d.squared_length()));
  }
  return m;
}

// The square [0, 1]^2 in the plane z = 0, an n x n grid of vertices, each cell cut in two
// along alternating diagonals.
template <typename PolygonMesh = Mesh>
PolygonMesh plane_patch(std::size_t n)
{
  PolygonMesh m;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> v;
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      v.push_back(add_vertex(Point(double(i) / double(n - 1), double(j) / double(n - 1), 0), m));
  for(std::size_t j = 0; j + 1 < n; ++j)
    for(std::size_t i = 0; i + 1 < n; ++i)
    {
      const auto a = v[j * n + i], b = v[j * n + i + 1], c = v[(j + 1) * n + i + 1], d = v[(j + 1) * n + i];
      if((i + j) % 2 == 0)
      {
        CGAL::Euler::add_face(std::array<decltype(a), 3>{a, b, c}, m);
        CGAL::Euler::add_face(std::array<decltype(a), 3>{a, c, d}, m);
      }
      else
      {
        CGAL::Euler::add_face(std::array<decltype(a), 3>{a, b, d}, m);
        CGAL::Euler::add_face(std::array<decltype(a), 3>{b, c, d}, m);
      }
    }
  return m;
}

// Moves every vertex uniformly at random inside a ball of radius r (seeded).
template <typename PolygonMesh>
void add_noise(PolygonMesh& m, double r, unsigned int seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  auto vpm = get(CGAL::vertex_point, m);
  for(auto v : vertices(m))
  {
    Vector d;
    do
      d = Vector(u(rng), u(rng), u(rng));
    while(d.squared_length() > 1);
    put(vpm, v, get(vpm, v) + r * d);
  }
}

template <typename PolygonMesh>
std::vector<Point> points(const PolygonMesh& m)
{
  std::vector<Point> result;
  for(auto v : vertices(m))
    result.push_back(get(CGAL::vertex_point, m, v));
  return result;
}

// Bit-for-bit equality of two point lists.
inline bool identical(const std::vector<Point>& a, const std::vector<Point>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!(a[i].x() == b[i].x() && a[i].y() == b[i].y() && a[i].z() == b[i].z()))
      return false;
  return true;
}

inline double mean_edge_length(const Mesh& m)
{
  double sum = 0;
  for(auto e : edges(m))
    sum += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  return sum / double(num_edges(m));
}

} // namespace test

#endif // CGAL_CONSTRAINED_FAIRING_TEST_SUPPORT_H
