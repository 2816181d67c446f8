// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise estimate's measure, shared by meshes (estimate_noise_level.h) and point sets
// (estimate_noise_level_of_points.h): each point's height over a cubic fitted to the points
// around it, divided by its variance factor, and the noise radius that the median of the
// squared heights gives.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NOISE_HEIGHTS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NOISE_HEIGHTS_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// The least number of points around a vertex for its cubic fit (ten coefficients).
constexpr std::size_t noise_fit_points = 14;

// The median of the squared normalized heights (cubic_residual()) of a surface with noise
// uniform in a ball of radius r, over r^2: 0.1206 for the noise alone (the height along a
// direction has the density 3 (1 - (z/r)^2) / (4 r)), 0.106 with the fit's own error, measured
// on noisy planes (regular grids, noise from 0.05 to 0.5 edge length), where the shape adds
// nothing.
constexpr double noise_median_ratio = 0.106;

// The height of `p` over the cubic height field fitted by least squares to `ring` (points
// around p, not p) in the frame of normal `n` centred at p, and the variance factor 1 + h of
// that height for independent heights of unit variance: h = e_0^T (A^T A)^-1 e_0 is the
// variance of the fit's value at p. Returns false when the fit is ill-posed. A cubic rather
// than a quadric: on the coarse meshes of the benchmark set, the part of the shape that the
// fit misses was 15-30 % smaller.
inline bool cubic_residual(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const std::vector<Eigen::Vector3d>& ring,
                           double& residual, double& factor)
{
  using Matrix = Eigen::Matrix<double, 10, 10>;
  using Vector = Eigen::Matrix<double, 10, 1>;
  const Eigen::Vector3d u = n.unitOrthogonal(), w = n.cross(u);
  double scale = 0;
  for(const Eigen::Vector3d& q : ring)
    scale += (q - p).norm();
  scale /= double(ring.size());
  if(!(scale > 0))
    return false;
  Matrix AtA = Matrix::Zero();
  Vector Atz = Vector::Zero();
  for(const Eigen::Vector3d& q : ring)
  {
    const Eigen::Vector3d d = (q - p) / scale;
    const double x = d.dot(u), y = d.dot(w);
    Vector a;
    a << 1, x, y, x * x, x * y, y * y, x * x * x, x * x * y, x * y * y, y * y * y;
    AtA += a * a.transpose();
    Atz += d.dot(n) * a;
  }
  const Eigen::LDLT<Matrix> ldlt(AtA);
  if(ldlt.info() != Eigen::Success || !ldlt.isPositive())
    return false;
  const Vector c = ldlt.solve(Atz);
  const Vector e0 = ldlt.solve(Vector::Unit(0));
  factor = 1 + e0[0];
  residual = -c[0] * scale;
  // A fit whose value at p varies ten times more than one height is too poorly conditioned
  // to tell noise from shape.
  return std::isfinite(residual) && std::isfinite(factor) && e0[0] >= 0 && e0[0] < 10;
}

// The radius of noise uniform in a ball whose squared heights have the median of `heights`
// (each divided by its variance factor); 0 when there is none.
inline double noise_radius(std::vector<double>& heights)
{
  if(heights.empty())
    return 0;
  const auto middle = heights.begin() + std::ptrdiff_t(heights.size() / 2);
  std::nth_element(heights.begin(), middle, heights.end());
  return std::sqrt(*middle / noise_median_ratio);
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NOISE_HEIGHTS_H
