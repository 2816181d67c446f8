// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The faces' unit normals, areas and centroids at some points: what the normal filters
// (Normal_filter.h, Guided_normal_filter.h) start from and change, and the weights they share.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_NORMALS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_NORMALS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Face_normals
{
  std::vector<Eigen::Vector3d> normal; // unit, zero for a face of zero area
  std::vector<Eigen::Vector3d> centroid;
  std::vector<double> area;

  // The faces of `mesh` at the points X.
  void set(const Hinge_mesh& mesh, const Points& X)
  {
    const std::size_t nf = mesh.triangles.size();
    normal.resize(nf);
    centroid.resize(nf);
    area.resize(nf);
    parallel_for_blocks(nf, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t f = begin; f < end; ++f)
      {
        const Eigen::Vector3d n = area_normal(mesh, X, f);
        const double length = n.norm();
        area[f] = length / 2;
        normal[f] = length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
        centroid[f] = Constrained_fairing::centroid(mesh, X, f);
      }
    });
  }

  // The filters' two Gaussians: in the distance between centroids, as wide as the mean distance
  // between edge neighbours', and in the difference of two unit vectors, `sigma` wide; false
  // where that mean is not positive (no hinge), and nothing to filter.
  bool set_widths(const Hinge_mesh& mesh, double sigma)
  {
    double sum = 0;
    for(const Hinge& h : mesh.hinges)
      sum += (centroid[h.f[0]] - centroid[h.f[1]]).norm();
    const double spacing = mesh.hinges.empty() ? 0 : sum / double(mesh.hinges.size());
    m_spatial = 1 / (2 * spacing * spacing);
    m_range = 1 / (2 * sigma * sigma);
    return spacing > 0;
  }

  // Face g's weight in face f's filtered normal: its area times the two Gaussians, of the
  // distance between their centroids and of the difference between a and b (their normals, or
  // their guides).
  double weight(std::size_t f, std::size_t g, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
  {
    return area[g] * std::exp(-m_spatial * (centroid[f] - centroid[g]).squaredNorm()) *
           std::exp(-m_range * (a - b).squaredNorm());
  }

private:
  double m_spatial = 0, m_range = 0;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FACE_NORMALS_H
