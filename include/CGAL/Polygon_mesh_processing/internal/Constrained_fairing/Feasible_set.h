// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feasible set Omega: every vertex within epsilon of its input position, in a ball or a
// box. The bound is a promise to the user, so membership is decided the way a user checks it,
// in double arithmetic with no tolerance, and every projection lands inside by that test.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEASIBLE_SET_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEASIBLE_SET_H

#include <CGAL/Polygon_mesh_processing/constrained_fairing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>

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

class Feasible_set
{
public:
  Feasible_set(const Points& X0, double eps, Deviation_bound shape)
    : m_X0(X0), m_eps(eps), m_shape(shape)
  {
    if(m_shape == Deviation_bound::BOX)
    {
      m_lower.resize(X0.rows(), 3);
      m_upper.resize(X0.rows(), 3);
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
  }

  double epsilon() const { return m_eps; }

  bool contains(const Points& X, std::size_t i) const
  {
    const double* q = X.data() + 3 * i;
    if(m_shape == Deviation_bound::BALL)
      return is_in_ball(q, m_X0.data() + 3 * i, m_eps);
    for(std::size_t k = 3 * i; k < 3 * i + 3; ++k)
      if(!(m_lower.data()[k] <= X.data()[k] && X.data()[k] <= m_upper.data()[k]))
        return false;
    return true;
  }

  // X = P(X), the closest point of Omega (up to the last bit, which is chosen inwards)
  void project(Points& X) const
  {
    for(std::size_t i = 0; i < static_cast<std::size_t>(X.rows()); ++i)
      project(X, i);
  }

  // Projects the direction V onto the face of Omega that contains Y: the coordinates at a
  // bound are fixed (box), a vertex on its sphere moves in the sphere's tangent plane (ball).
  // This is an orthogonal projection, so restricted to that face the reduced Hessian stays
  // symmetric positive definite.
  void restrict_to_face(const Points& Y, Points& V) const
  {
    for(std::size_t i = 0; i < static_cast<std::size_t>(Y.rows()); ++i)
    {
      if(m_shape == Deviation_bound::BOX)
      {
        for(std::size_t k = 3 * i; k < 3 * i + 3; ++k)
          if(Y.data()[k] <= m_lower.data()[k] || Y.data()[k] >= m_upper.data()[k])
            V.data()[k] = 0;
        continue;
      }
      const Eigen::Vector3d d = point(Y, i) - point(m_X0, i);
      const double r = norm(d);
      if(r >= m_eps - sphere_tolerance(i))
      {
        if(r > 0)
        {
          const Eigen::Vector3d n = d / r;
          point(V, i) -= n.dot(point(V, i)) * n;
        }
        else // epsilon below the rounding error of the coordinates: the vertex cannot move
          point(V, i).setZero();
      }
    }
  }

  // The largest Euclidean distance |x_i - x0_i| over all vertices.
  double max_deviation(const Points& X) const
  {
    double d2 = 0;
    for(std::size_t i = 0; i < static_cast<std::size_t>(X.rows()); ++i)
      d2 = (std::max)(d2, (point(X, i) - point(m_X0, i)).squaredNorm());
    return std::sqrt(d2);
  }

private:
  void project(Points& X, std::size_t i) const
  {
    if(m_shape == Deviation_bound::BOX)
    {
      for(std::size_t k = 3 * i; k < 3 * i + 3; ++k)
        X.data()[k] = (std::min)((std::max)(X.data()[k], m_lower.data()[k]), m_upper.data()[k]);
      return;
    }
    if(contains(X, i))
      return;
    const Eigen::Vector3d c = point(m_X0, i);
    const Eigen::Vector3d d = point(X, i) - c;
    // Scale the offset onto the sphere. Rounding the coordinates may leave the result just
    // outside; aim a little inside then, by a slack that starts at that rounding error. The
    // centre, reached at worst, is inside. An offset that overflows (X must be finite, not
    // X - c) goes to the centre.
    const double r = norm(d);
    if(r < std::numeric_limits<double>::infinity())
      for(double slack = 0; slack < m_eps; slack = (slack == 0) ? rounding_error(i) : 2 * slack)
      {
        point(X, i) = c + ((m_eps - slack) / r) * d;
        if(contains(X, i))
          return;
      }
    point(X, i) = c;
  }

  // |d|, without underflow to 0 or overflow to infinity where |d| itself is in range (the
  // plain formula first: the careful one is several times slower).
  static double norm(const Eigen::Vector3d& d)
  {
    const double r = d.norm();
    return (r > 0 && r < std::numeric_limits<double>::infinity()) ? r : d.stableNorm();
  }

  double rounding_error(std::size_t i) const
  {
    return (std::max)(std::numeric_limits<double>::epsilon() * (point(m_X0, i).lpNorm<Eigen::Infinity>() + m_eps),
                      std::numeric_limits<double>::denorm_min());
  }

  // How far inside its sphere a vertex still counts as on it: what projection may leave.
  double sphere_tolerance(std::size_t i) const { return 8 * rounding_error(i); }

  const Points& m_X0;
  double m_eps;
  Deviation_bound m_shape;
  Points m_lower, m_upper; // the box, per coordinate
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_FEASIBLE_SET_H
