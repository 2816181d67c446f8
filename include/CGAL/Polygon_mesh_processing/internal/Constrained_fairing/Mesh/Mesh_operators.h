// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The discrete operators on the triangles of a Hinge_mesh that several parts of the solver
// share: the triangles around each vertex, the mean of a vertex's neighbours, and the test
// that says which triangles are degenerate. One definition each, so that the parts agree on
// what a neighbour or a degenerate triangle is, to the last bit.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_OPERATORS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_OPERATORS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Rows_by_vertex.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The triangles around each vertex, in increasing order.
inline Rows_by_vertex<Index> vertex_triangles(const Hinge_mesh& mesh)
{
  return Rows_by_vertex<Index>(mesh.number_of_vertices, [&](const auto& add) {
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for(Index v : mesh.triangles[f])
        add(v, static_cast<Index>(f));
  });
}

// The mean of each vertex's neighbours, taken from its triangles: an interior edge counts
// twice (once per triangle), a border edge once, so that a border vertex's mean lies along the
// border rather than inside the surface.
class Neighbour_mean
{
public:
  explicit Neighbour_mean(const Hinge_mesh& mesh) : Neighbour_mean(mesh, [](std::size_t) { return true; }) {}

  // Only for the vertices i for which `selected(i)`; the others get no neighbours.
  template <typename Selected>
  Neighbour_mean(const Hinge_mesh& mesh, const Selected& selected)
    : Neighbour_mean(mesh.triangles, mesh.number_of_vertices, selected)
  {}

  // The same over any triangles of n vertices (a soup).
  template <typename Selected>
  Neighbour_mean(const std::vector<std::array<Index, 3> >& triangles, std::size_t n, const Selected& selected)
    : m_triangles(triangles), m_count(n, 0.)
  {
    for(const auto& t : triangles)
      for(Index v : t)
        if(selected(std::size_t(v)))
          m_count[v] += 2;
  }

  // Sums the neighbours at the points X.
  void gather(const Points& X)
  {
    m_sum.setZero(X.rows(), 3);
    for(const auto& t : m_triangles)
      for(std::size_t k = 0; k < 3; ++k)
        if(m_count[t[k]] > 0)
          point(m_sum, t[k]) += point(X, t[(k + 1) % 3]) + point(X, t[(k + 2) % 3]);
  }

  // The number of vertex i's neighbours, 0 for a vertex in no triangle or not selected.
  double count(std::size_t i) const { return m_count[i]; }

  // Their sum and, where count(i) > 0, their mean at the last gather().
  Eigen::Map<const Eigen::Vector3d> sum(std::size_t i) const { return point(m_sum, i); }
  Eigen::Vector3d mean(std::size_t i) const { return sum(i) / m_count[i]; }

private:
  const std::vector<std::array<Index, 3> >& m_triangles;
  std::vector<double> m_count;
  Points m_sum;
};

// Each vertex's unit normal at the points X: the sum of its triangles' area normals,
// normalized; zero where that sum vanishes.
inline Points vertex_normals(const Hinge_mesh& mesh, const Points& X)
{
  Points N = Points::Zero(X.rows(), 3);
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const Eigen::Vector3d n = area_normal(mesh, X, f);
    for(Index v : mesh.triangles[f])
      point(N, v) += n;
  }
  for(std::size_t i = 0; i < static_cast<std::size_t>(N.rows()); ++i)
  {
    const double length = point(N, i).norm();
    if(length > 0)
      point(N, i) /= length;
    else
      point(N, i).setZero();
  }
  return N;
}

// The doubled area, relative to the longest squared edge, at or under which a triangle is
// degenerate (an angle of about a micro radian): its normal is then meaningless, and turns
// wildly under tiny moves (Bending_energy.h).
constexpr double degenerate_area = 1e-6;

// Which triangles are degenerate at the points X; a triangle whose area is NaN is.
inline std::vector<bool> degenerate_triangles(const Hinge_mesh& mesh, const Points& X)
{
  std::vector<bool> degenerate(mesh.triangles.size());
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const auto& t = mesh.triangles[f];
    double longest = 0;
    for(std::size_t k = 0; k < 3; ++k)
      longest = (std::max)(longest, (point(X, t[k]) - point(X, t[(k + 1) % 3])).squaredNorm());
    degenerate[f] = !(area_normal(mesh, X, f).norm() > degenerate_area * longest);
  }
  return degenerate;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_MESH_OPERATORS_H
