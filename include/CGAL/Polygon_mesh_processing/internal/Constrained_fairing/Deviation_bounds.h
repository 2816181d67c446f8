// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feasible set Omega, a product of one small set per vertex around its input position:
// the ball of radius epsilon, or the paper's box of side 2 epsilon. The solvers are templated
// on the bound, so no per-vertex loop branches on its shape. The bound is a promise to the
// user, so membership is decided the way a user checks it, in double arithmetic with no
// tolerance, and every projection lands inside by that test.
//
// Each bound also says which face of its set a vertex is on (its sphere, or the sides of its
// box it touches), and restricts a displacement to that face; Active_set.h collects them.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DEVIATION_BOUNDS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DEVIATION_BOUNDS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Points.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// |q - c| <= eps as a user computes it: the squared distance against eps^2, and its square
// root against eps (both, since rounding may separate them).
inline bool is_in_ball(const double* q, const double* c, double eps)
{
  const double dx = q[0] - c[0], dy = q[1] - c[1], dz = q[2] - c[2];
  const double d2 = dx * dx + dy * dy + dz * dz;
  return d2 <= eps * eps && std::sqrt(d2) <= eps;
}

// |d|, without underflow to 0 or overflow to infinity where |d| itself is in range (the
// plain formula first: the careful one is several times slower).
inline double robust_norm(const Eigen::Vector3d& d)
{
  const double r = d.norm();
  return (r > 0 && r < std::numeric_limits<double>::infinity()) ? r : d.stableNorm();
}

// What the bounds share: the input points, epsilon, and the loops over all vertices.
template <typename Bound>
class Deviation_bound_base
{
public:
  Deviation_bound_base(const Points& X0, double eps) : m_X0(X0), m_eps(eps) {}

  double epsilon() const { return m_eps; }
  const Points& input_points() const { return m_X0; }

  // X = P(X), the closest point of Omega (up to the last bit, which is chosen inwards)
  void project(Points& X) const
  {
    parallel_for_blocks(static_cast<std::size_t>(X.rows()), [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t i = begin; i < end; ++i)
        static_cast<const Bound&>(*this).project(X, i);
    });
  }

  // The largest Euclidean distance |x_i - x0_i| over all vertices.
  double max_deviation(const Points& X) const
  {
    double d2 = 0;
    for(std::size_t i = 0; i < static_cast<std::size_t>(X.rows()); ++i)
      d2 = (std::max)(d2, (point(X, i) - point(m_X0, i)).squaredNorm());
    return std::sqrt(d2);
  }

protected:
  // The rounding error of vertex i's coordinates.
  double rounding_error(std::size_t i) const
  {
    return (std::max)(std::numeric_limits<double>::epsilon() * (point(m_X0, i).template lpNorm<Eigen::Infinity>() + m_eps),
                      std::numeric_limits<double>::denorm_min());
  }

  const Points& m_X0;
  double m_eps;
};

// |p - p0| <= epsilon
class Ball_bound : public Deviation_bound_base<Ball_bound>
{
public:
  // A vertex on its sphere: the outward unit normal there (zero when epsilon is below the
  // rounding error of the coordinates, and the vertex cannot move at all).
  using Face = Eigen::Vector3d;

  Ball_bound(const Points& X0, double eps) : Deviation_bound_base<Ball_bound>(X0, eps) {}

  bool contains(const Points& X, std::size_t i) const
  {
    return is_in_ball(X.data() + 3 * i, m_X0.data() + 3 * i, m_eps);
  }

  using Deviation_bound_base<Ball_bound>::project;

  void project(Points& X, std::size_t i) const
  {
    if(contains(X, i))
      return;
    const Eigen::Vector3d c = point(m_X0, i);
    const Eigen::Vector3d d = point(X, i) - c;
    // Scale the offset onto the sphere. Rounding the coordinates may leave the result just
    // outside; aim a little inside then, by a slack that starts at that rounding error. The
    // centre, reached at worst, is inside. An offset that overflows (X must be finite, not
    // X - c) goes to the centre.
    const double r = robust_norm(d);
    if(r < std::numeric_limits<double>::infinity())
      for(double slack = 0; slack < m_eps; slack = (slack == 0) ? rounding_error(i) : 2 * slack)
      {
        point(X, i) = c + ((m_eps - slack) / r) * d;
        if(contains(X, i))
          return;
      }
    point(X, i) = c;
  }

  // Whether vertex i is on its sphere (up to what projection may leave), and then its face.
  bool is_on_boundary(const Points& X, std::size_t i, Face& face) const
  {
    const Eigen::Vector3d d = point(X, i) - point(m_X0, i);
    const double r = robust_norm(d);
    if(r < m_eps - 8 * rounding_error(i))
      return false;
    face = r > 0 ? Eigen::Vector3d(d / r) : Eigen::Vector3d::Zero();
    return true;
  }

  // Whether the descent direction -g pushes a vertex on `face` out of its sphere (then it
  // moves in the tangent plane); one that -g pulls inwards is free.
  static bool keep_blocked(Face& face, const Eigen::Vector3d& g) { return face.isZero() || face.dot(g) < 0; }

  // Projects v onto the tangent plane of the sphere (an orthogonal projection, so that a
  // symmetric positive definite operator restricted to the face stays so).
  static void restrict(const Face& face, Eigen::Map<Eigen::Vector3d> v)
  {
    if(face.isZero())
      v.setZero();
    else
      v -= face.dot(v) * face;
  }
};

// |p_k - p0_k| <= epsilon for each coordinate k
class Box_bound : public Deviation_bound_base<Box_bound>
{
public:
  // A vertex on its box: the sides it touches, per coordinate -1 (lower), +1 (upper) or 0.
  using Face = Eigen::Vector3i;

  Box_bound(const Points& X0, double eps)
    : Deviation_bound_base<Box_bound>(X0, eps), m_lower(X0.rows(), 3), m_upper(X0.rows(), 3)
  {
    for(Eigen::Index k = 0; k < X0.size(); ++k)
    {
      const double c = X0.data()[k];
      // the closest doubles to c -+ eps whose difference to c, as computed, is <= eps
      double lo = c - eps, hi = c + eps;
      while(c - lo > eps)
        lo = std::nextafter(lo, c);
      while(hi - c > eps)
        hi = std::nextafter(hi, c);
      m_lower.data()[k] = lo;
      m_upper.data()[k] = hi;
    }
  }

  bool contains(const Points& X, std::size_t i) const
  {
    for(std::size_t k = 3 * i; k < 3 * i + 3; ++k)
      if(!(m_lower.data()[k] <= X.data()[k] && X.data()[k] <= m_upper.data()[k]))
        return false;
    return true;
  }

  using Deviation_bound_base<Box_bound>::project;

  void project(Points& X, std::size_t i) const
  {
    for(std::size_t k = 3 * i; k < 3 * i + 3; ++k)
      X.data()[k] = (std::min)((std::max)(X.data()[k], m_lower.data()[k]), m_upper.data()[k]);
  }

  bool is_on_boundary(const Points& X, std::size_t i, Face& face) const
  {
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t k = 3 * i + std::size_t(c);
      face[c] = X.data()[k] <= m_lower.data()[k] ? -1 : X.data()[k] >= m_upper.data()[k] ? 1 : 0;
    }
    return !face.isZero();
  }

  // Keeps the sides that the descent direction -g pushes the vertex out of; false if none.
  static bool keep_blocked(Face& face, const Eigen::Vector3d& g)
  {
    for(int c = 0; c < 3; ++c)
      if(!(face[c] * g[c] < 0))
        face[c] = 0;
    return !face.isZero();
  }

  // Fixes the coordinates at a side.
  static void restrict(const Face& face, Eigen::Map<Eigen::Vector3d> v)
  {
    for(int c = 0; c < 3; ++c)
      if(face[c] != 0)
        v[c] = 0;
  }

private:
  Points m_lower, m_upper; // the box, per coordinate
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DEVIATION_BOUNDS_H
