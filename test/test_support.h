// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes with a known true surface, seeded noise and a check macro for the tests.

#ifndef CGAL_CONSTRAINED_FAIRING_TEST_SUPPORT_H
#define CGAL_CONSTRAINED_FAIRING_TEST_SUPPORT_H

#include "seeded_noise.h"

#include "front_end/Mean_edge_length.h"

#include "triangle_tree.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <vector>

namespace test {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;

inline int failures = 0;

// Whether this build has AddressSanitizer (CI's sanitizer build), under which the tests run 3 to
// 10 times as slowly. There the heaviest cases run smaller: that build looks for memory errors
// and undefined behaviour, which the smaller cases reach through the same code, while the default
// build checks every result at full size.
#if defined(__SANITIZE_ADDRESS__)
#define CONSTRAINED_FAIRING_TEST_UNDER_SANITIZERS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CONSTRAINED_FAIRING_TEST_UNDER_SANITIZERS 1
#endif
#endif
#ifndef CONSTRAINED_FAIRING_TEST_UNDER_SANITIZERS
#define CONSTRAINED_FAIRING_TEST_UNDER_SANITIZERS 0
#endif
inline constexpr bool under_sanitizers = CONSTRAINED_FAIRING_TEST_UNDER_SANITIZERS != 0;

// A Surface_mesh as the solver sees it: its points in vertex index order and its hinges.
struct Indexed
{
  CGAL::Polygon_mesh_processing::internal::Constrained_fairing::Points X;
  CGAL::Polygon_mesh_processing::internal::Constrained_fairing::Hinge_mesh hinges;

  explicit Indexed(const Mesh& m) : X(num_vertices(m), 3), hinges(m, get(boost::vertex_index, m))
  {
    for(auto v : vertices(m))
    {
      const Point& p = m.point(v);
      X.row(v.idx()) << p.x(), p.y(), p.z();
    }
  }
};

#define CHECK(condition)                                                                      \
  do                                                                                          \
  {                                                                                           \
    if(!(condition))                                                                          \
    {                                                                                         \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl; \
      ++test::failures;                                                                       \
    }                                                                                         \
  } while(false)

// The relative RMS error of the gradient G of `value` at X against central differences of step
// h, over every `stride`-th coordinate (X is restored).
template <typename Value>
double gradient_error(CGAL::Polygon_mesh_processing::internal::Constrained_fairing::Points& X,
                      const CGAL::Polygon_mesh_processing::internal::Constrained_fairing::Points& G,
                      const Value& value, double h, Eigen::Index stride = 1)
{
  double error2 = 0, norm2 = 0;
  for(Eigen::Index k = 0; k < X.size(); k += stride)
  {
    double& c = X.data()[k];
    const double c0 = c;
    c = c0 + h;
    const double up = value(X);
    c = c0 - h;
    const double down = value(X);
    c = c0;
    const double fd = (up - down) / (2 * h);
    error2 += (fd - G.data()[k]) * (fd - G.data()[k]);
    norm2 += G.data()[k] * G.data()[k];
  }
  return norm2 > 0 ? std::sqrt(error2 / norm2) : std::numeric_limits<double>::infinity();
}

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

// The cube [0, 1]^3, each side an n x n grid of squares cut in two along alternating diagonals,
// facing outward: its 12 n edges on the cube's edges are its only sharp ones (90 degrees).
template <typename PolygonMesh = Mesh>
PolygonMesh grid_cube(std::size_t n)
{
  using Vertex = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  PolygonMesh m;
  std::map<std::array<std::size_t, 3>, Vertex> at;
  const auto vertex = [&](std::array<std::size_t, 3> g) {
    auto it = at.find(g);
    if(it == at.end())
      it = at.emplace(g, add_vertex(Point(double(g[0]) / double(n), double(g[1]) / double(n), double(g[2]) / double(n)), m)).first;
    return it->second;
  };
  for(std::size_t axis = 0; axis < 3; ++axis)
    for(std::size_t side : {std::size_t(0), n})
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = 0; j < n; ++j)
        {
          // (i, j) along the next two axes, whose cross product is `axis`: counterclockwise
          // seen from outside on the far side, clockwise on the near one.
          const auto corner = [&](std::size_t di, std::size_t dj) {
            std::array<std::size_t, 3> g;
            g[axis] = side;
            g[(axis + 1) % 3] = i + di;
            g[(axis + 2) % 3] = j + dj;
            return vertex(g);
          };
          std::array<Vertex, 4> q = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
          if(side == 0)
            std::swap(q[1], q[3]);
          const std::size_t d = (i + j) % 2;
          CGAL::Euler::add_face(std::array<Vertex, 3>{q[d], q[d + 1], q[(d + 2) % 4]}, m);
          CGAL::Euler::add_face(std::array<Vertex, 3>{q[d], q[(d + 2) % 4], q[(d + 3) % 4]}, m);
        }
  return m;
}

template <typename PolygonMesh>
std::vector<Point> points(const PolygonMesh& m)
{
  std::vector<Point> result;
  for(auto v : vertices(m))
    result.push_back(get(CGAL::vertex_point, m, v));
  return result;
}

// Bit-for-bit equality of two point lists (NaN equals the same NaN, 0 differs from -0).
inline bool identical(const std::vector<Point>& a, const std::vector<Point>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    for(int c = 0; c < 3; ++c)
    {
      const double x = a[i][c], y = b[i][c];
      if(std::memcmp(&x, &y, sizeof(double)) != 0)
        return false;
    }
  return true;
}

// Makes `fraction` of the faces of m degenerate, chosen at random (seeded), in turn by
// moving a vertex onto the line through the other two (collinear vertices), onto another
// vertex (duplicated vertices), or all three onto their centroid (zero area, zero edges).
// Neighbouring faces get distorted too. Returns the number of faces changed.
template <typename PolygonMesh>
std::size_t make_degenerate(PolygonMesh& m, double fraction, unsigned int seed)
{
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  std::vector<face_descriptor> chosen(faces(m).begin(), faces(m).end());
  std::mt19937 rng(seed);
  std::shuffle(chosen.begin(), chosen.end(), rng);
  chosen.resize(static_cast<std::size_t>(fraction * double(chosen.size())));
  std::uniform_real_distribution<double> u(0.2, 0.8);
  auto vpm = get(CGAL::vertex_point, m);
  for(std::size_t k = 0; k < chosen.size(); ++k)
  {
    const auto h = halfedge(chosen[k], m);
    const auto a = source(h, m), b = target(h, m), c = target(next(h, m), m);
    const Point pa = get(vpm, a), pb = get(vpm, b), pc = get(vpm, c);
    switch(k % 3)
    {
    case 0: put(vpm, c, pa + u(rng) * (pb - pa)); break;
    case 1: put(vpm, b, pa); break;
    default:
    {
      const Point g = CGAL::centroid(pa, pb, pc);
      put(vpm, a, g);
      put(vpm, b, g);
      put(vpm, c, g);
    }
    }
  }
  return chosen.size();
}

// The faces whose area is below 1e-12 of the mean face area.
template <typename PolygonMesh>
std::size_t number_of_degenerate_faces(const PolygonMesh& m)
{
  std::vector<double> areas;
  double sum = 0;
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    const auto vpm = get(CGAL::vertex_point, m);
    areas.push_back(std::sqrt(CGAL::squared_area(get(vpm, source(h, m)), get(vpm, target(h, m)),
                                                 get(vpm, target(next(h, m), m)))));
    sum += areas.back();
  }
  const double threshold = 1e-12 * sum / double(areas.size());
  return std::size_t(std::count_if(areas.begin(), areas.end(), [&](double a) { return a <= threshold; }));
}

// The RMS distance of the vertices of `result` to the surface of `reference`.
inline double surface_rms(const Mesh& result, const Mesh& reference)
{
  Triangle_tree<K, Mesh> tree(faces(reference).first, faces(reference).second, reference);
  double sum = 0;
  for(auto v : vertices(result))
    sum += tree.squared_distance(result.point(v));
  return std::sqrt(sum / double(num_vertices(result)));
}

// The largest violation of the bound, as a user computes it: 0 or less when it holds exactly
// (the ball's squared distance against eps^2 and its square root against eps; the box's
// coordinates one by one). NaN in a point makes it NaN, which no test takes for "holds".
template <typename Shape>
double bound_violation(const std::vector<Point>& out, const std::vector<Point>& in, double eps, Shape shape)
{
  double violation = 0;
  for(std::size_t i = 0; i < in.size(); ++i)
  {
    if(shape == Shape::BALL)
    {
      const double d2 = CGAL::squared_distance(out[i], in[i]);
      violation = (std::max)({violation, d2 - eps * eps, std::sqrt(d2) - eps});
      if(std::isnan(d2))
        return d2;
    }
    else
      for(int c = 0; c < 3; ++c)
      {
        const double d = std::abs(out[i][c] - in[i][c]);
        if(std::isnan(d))
          return d;
        violation = (std::max)(violation, d - eps);
      }
  }
  return violation;
}

// The smallest angle (degrees) of the triangles of a soup.
inline double smallest_angle(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3> >& triangles)
{
  double smallest = 180;
  for(const auto& t : triangles)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const Vector u = points[t[(k + 1) % 3]] - points[t[k]], v = points[t[(k + 2) % 3]] - points[t[k]];
      const double angle = std::atan2(std::sqrt(CGAL::cross_product(u, v).squared_length()), u * v);
      smallest = (std::min)(smallest, angle * 180 / CGAL_PI);
    }
  return smallest;
}

// The bending energy summed hinge by hinge from its formula (Bending_energy.h), with no
// regularization and no hinge left out: the mesh's, for a mesh without degenerate triangles.
inline double plain_bending_energy(const Mesh& m)
{
  double sum = 0;
  for(auto e : edges(m))
  {
    if(is_border(e, m))
      continue;
    const auto h = halfedge(e, m), o = opposite(h, m);
    const Point &a = m.point(source(h, m)), &b = m.point(target(h, m));
    const Vector N1 = CGAL::cross_product(b - a, m.point(target(next(h, m), m)) - a);
    const Vector N2 = CGAL::cross_product(a - b, m.point(target(next(o, m), m)) - b);
    const double l1 = std::sqrt(N1.squared_length()), l2 = std::sqrt(N2.squared_length());
    sum += 1.5 * CGAL::squared_distance(a, b) / (l1 + l2) * 0.5 * (N1 / l1 - N2 / l2).squared_length();
  }
  return sum;
}

using Constrained_fairing_front_end::mean_edge_length;

} // namespace test

#endif // CGAL_CONSTRAINED_FAIRING_TEST_SUPPORT_H
