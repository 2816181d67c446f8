// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex coordinates as the solver sees them: an n x 3 matrix, one row per vertex, the paper's
// point x in R^{3n}, and the few operations on it that every part of the solver uses.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINTS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINTS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Vertex and face indices: 32 bits, as in CGAL::Surface_mesh, halve the memory of the
// connectivity arrays on large scans.
using Index = std::uint32_t;

inline Eigen::Map<const Eigen::Vector3d> point(const Points& X, std::size_t i)
{
  return Eigen::Map<const Eigen::Vector3d>(X.data() + 3 * i);
}

inline Eigen::Map<Eigen::Vector3d> point(Points& X, std::size_t i)
{
  return Eigen::Map<Eigen::Vector3d>(X.data() + 3 * i);
}

// Vertex displacements stored in single precision, where half the memory matters more than
// the digits (the quasi-Newton method's history).
using Float_points = Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>;

// <A, B> over all coordinates
inline double dot(const Points& A, const Points& B) { return A.cwiseProduct(B).sum(); }

// <A, B> over the rows [begin, end), in double, for a pass over blocks of Parallel_for.h. Four
// running sums: with one, each addition waits for the one before, and the loop runs at the
// adder's latency.
template <typename A, typename B>
double dot_rows(const A& a, const B& b, std::size_t begin, std::size_t end)
{
  const auto* pa = a.data() + 3 * begin;
  const auto* pb = b.data() + 3 * begin;
  const std::size_t n = 3 * (end - begin);
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  std::size_t i = 0;
  for(; i + 4 <= n; i += 4)
  {
    s0 += double(pa[i]) * double(pb[i]);
    s1 += double(pa[i + 1]) * double(pb[i + 1]);
    s2 += double(pa[i + 2]) * double(pb[i + 2]);
    s3 += double(pa[i + 3]) * double(pb[i + 3]);
  }
  for(; i < n; ++i)
    s0 += double(pa[i]) * double(pb[i]);
  return (s0 + s1) + (s2 + s3);
}

// <G, Y - X>
inline double dot_with_difference(const Points& G, const Points& Y, const Points& X, std::vector<double>& partial)
{
  return parallel_sum(static_cast<std::size_t>(G.rows()), partial, [&](std::size_t begin, std::size_t end) {
    const double *g = G.data() + 3 * begin, *y = Y.data() + 3 * begin, *x = X.data() + 3 * begin;
    const std::size_t n = 3 * (end - begin);
    double s0 = 0, s1 = 0, s2 = 0;
    for(std::size_t i = 0; i < n; i += 3)
    {
      s0 += g[i] * (y[i] - x[i]);
      s1 += g[i + 1] * (y[i + 1] - x[i + 1]);
      s2 += g[i + 2] * (y[i + 2] - x[i + 2]);
    }
    return (s0 + s1) + s2;
  });
}

// The scale, a power of two, at which the energy and its Hessian are evaluated: 1 when the
// largest coordinate of X is within [2^-100, 2^100], where squared areas of any mesh that is
// not a single point fit in double; otherwise the one that brings it into [1/2, 1), for meshes
// in kilometres or nanometres of absurd units. A power of two scales every intermediate
// result exactly.
inline double unit_scale(const Points& X)
{
  const double largest = X.size() > 0 ? X.cwiseAbs().maxCoeff() : 0;
  int exponent = 0;
  std::frexp(largest, &exponent);
  if(!(largest > 0) || (exponent > -100 && exponent <= 100))
    return 1;
  return std::ldexp(1., (std::max)(-1000, (std::min)(1000, -exponent)));
}

// Points at the scale unit_scale() gives the input X0, for the terms evaluated there: X itself
// when that scale is 1, else a copy scaled by it, whose storage is kept from one call to the
// next.
class Unit_scaled_points
{
public:
  explicit Unit_scaled_points(const Points& X0) : m_scale(unit_scale(X0)) {}

  double scale() const { return m_scale; }

  const Points& operator()(const Points& X)
  {
    if(m_scale == 1)
      return X;
    m_scaled.noalias() = m_scale * X;
    return m_scaled;
  }

private:
  double m_scale;
  Points m_scaled;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_POINTS_H
