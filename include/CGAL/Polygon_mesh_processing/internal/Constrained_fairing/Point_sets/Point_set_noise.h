// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise estimate's heights on a point set (estimate_noise_level_of_points.h): each point's
// ring is its k nearest neighbours, its frame the plane that fits them best.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_NOISE_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_NOISE_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Denoising/Noise_heights.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Point_sets/Point_neighbours.h>

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The unit normal of the plane that fits `ring` best (its points' covariance's eigenvector of
// the smallest eigenvalue), zero when the ring spans no plane.
inline Eigen::Vector3d fitted_plane_normal(const std::vector<Eigen::Vector3d>& ring)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(const Eigen::Vector3d& q : ring)
    mean += q;
  mean /= double(ring.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(const Eigen::Vector3d& q : ring)
    covariance += (q - mean) * (q - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  if(eigen.info() != Eigen::Success || !(eigen.eigenvalues()[1] > 0))
    return Eigen::Vector3d::Zero();
  return eigen.eigenvectors().col(0);
}

// The squared heights (Noise_heights.h) of the n > k points X over the cubics fitted to their
// `k` nearest neighbours; a point whose fit is ill-posed has none.
inline std::vector<double> point_set_noise_heights(const Points& X, std::size_t k)
{
  const std::size_t n = std::size_t(X.rows());
  const Point_neighbours neighbours(X, k);
  std::vector<double> squared(n, -1);
  parallel_for_blocks(n, [&](std::size_t begin, std::size_t end, std::size_t) {
    std::vector<Eigen::Vector3d> ring;
    for(std::size_t i = begin; i < end; ++i)
    {
      ring.clear();
      for(const Index* j = neighbours.begin(i); j != neighbours.end(i); ++j)
        ring.push_back(point(X, std::size_t(*j)));
      const Eigen::Vector3d normal = fitted_plane_normal(ring);
      double residual = 0, factor = 1;
      if(normal.squaredNorm() > 0 && cubic_residual(point(X, i), normal, ring, residual, factor))
        squared[i] = residual * residual / factor;
    }
  });
  std::vector<double> heights;
  for(double h : squared)
    if(h >= 0)
      heights.push_back(h);
  return heights;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINT_SET_NOISE_H
