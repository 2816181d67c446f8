// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Each point's tangent fan: its neighbours projected into its tangent plane, their Delaunay
// triangulation (CGAL's Delaunay_triangulation_2), and the triangles around the point there.
// Its row of the Laplacian: the cotangent weights of the fan in the plane, half the cotangents
// of the angles opposite each edge to a neighbour, which Delaunay makes nonnegative and which
// reproduce linear functions, so that the row vanishes on any plane (Sharp and Crane, "A
// Laplacian for nonmanifold triangle meshes", SGP 2020, build theirs from the same local
// triangulations). Why each point keeps its own row, not their symmetric mean: the mean loses
// the linear precision, and the bending energy would no longer be zero on planes. Why the
// weights are taken in the plane, not in space: the noise is mostly along the normal, and
// there the angles are the sampling's, not the noise's. A point on the border of its
// triangulation (a scan's border) has a fan but no row: as at a mesh's border, no bending is
// measured there. The fans' triangles, oriented by the normals, also serve the shared
// operators: the vertex normals at the current points and the neighbours of the smoothed
// start (Mesh_operators.h).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_TANGENT_FANS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_TANGENT_FANS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_neighbours.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// One point's fan: its triangles (the point first, counterclockwise about its normal) and,
// if it is closed, its row's weights, one per neighbour in it.
struct Tangent_fan
{
  std::vector<std::array<Index, 3> > triangles;
  std::vector<std::pair<Index, double> > weights; // empty: the fan is open, or none
  bool is_closed() const { return !weights.empty(); }
};

namespace tangent_fan {

using Kernel = Exact_predicates_inexact_constructions_kernel;
using Vertex_base = Triangulation_vertex_base_with_info_2<Index, Kernel>;
using Data_structure = Triangulation_data_structure_2<Vertex_base>;
using Triangulation = Delaunay_triangulation_2<Kernel, Data_structure>;

// Two unit vectors that make a right-handed frame with the unit normal n.
inline std::array<Eigen::Vector3d, 2> tangent_frame(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d other = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = n.cross(other).normalized();
  return {u, n.cross(u)};
}

// The cotangent of the angle at a of the triangle (a, b, c) of the plane.
inline double cotangent(const Kernel::Point_2& a, const Kernel::Point_2& b, const Kernel::Point_2& c)
{
  const double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = c.x() - a.x(), vy = c.y() - a.y();
  return (ux * vx + uy * vy) / std::abs(ux * vy - uy * vx);
}

// The fan of the centre of `dt`, vertex `centre` of index i.
inline Tangent_fan fan_of(const Triangulation& dt, Triangulation::Vertex_handle centre)
{
  Tangent_fan fan;
  bool closed = true;
  std::vector<std::pair<Index, double> > weights;
  const auto add = [&weights](Index j, double w) {
    for(auto& [k, sum] : weights)
      if(k == j)
      {
        sum += w;
        return;
      }
    weights.emplace_back(j, w);
  };
  auto f = dt.incident_faces(centre), done = f;
  do
  {
    if(dt.is_infinite(f))
    {
      closed = false;
      continue;
    }
    const int c = f->index(centre);
    const auto a = f->vertex(Triangulation::ccw(c)), b = f->vertex(Triangulation::cw(c));
    fan.triangles.push_back({centre->info(), a->info(), b->info()});
    add(b->info(), cotangent(a->point(), centre->point(), b->point()) / 2);
    add(a->info(), cotangent(b->point(), a->point(), centre->point()) / 2);
  } while(++f != done);
  for(const auto& entry : weights)
    closed = closed && std::isfinite(entry.second); // a fan whose triangle is flat in doubles
  if(closed)
    fan.weights = std::move(weights);
  return fan;
}

} // namespace tangent_fan

// The fans of the points X with unit normals N, from their `neighbours` that are not
// `isolated`; an isolated point, or one whose neighbours lie on a line in its plane, gets none.
inline std::vector<Tangent_fan> tangent_fans(const Points& X, const Points& N, const Point_neighbours& neighbours,
                                             const std::vector<bool>& isolated)
{
  namespace T = tangent_fan;
  const std::size_t n = neighbours.size();
  std::vector<Tangent_fan> fans(n);
  parallel_for_blocks(n, [&](std::size_t begin, std::size_t end, std::size_t) {
    for(std::size_t i = begin; i < end; ++i)
    {
      if(isolated[i])
        continue;
      const auto frame = T::tangent_frame(point(N, i));
      T::Triangulation dt;
      const auto centre = dt.insert(T::Kernel::Point_2(0, 0));
      centre->info() = Index(i);
      for(const Index* j = neighbours.begin(i); j != neighbours.end(i); ++j)
        if(!isolated[*j])
        {
          const Eigen::Vector3d d = point(X, *j) - point(X, i);
          const auto v = dt.insert(T::Kernel::Point_2(d.dot(frame[0]), d.dot(frame[1])));
          if(v != centre)
            v->info() = *j;
        }
      if(dt.dimension() == 2)
        fans[i] = T::fan_of(dt, centre);
    }
  });
  return fans;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_TANGENT_FANS_H
