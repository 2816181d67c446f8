// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feasible set Omega, a product of one small set per vertex: the ball of radius r_i
// around its input position, or an axis-aligned box of half-extents (h_x, h_y, h_z)_i around
// its input position or around a centre of its own (a voxel cell). Each vertex has its own
// size; a size 0 pins the vertex. The solvers are templated on the bound, so no per-vertex
// loop branches on its shape. The bound is a promise to the user, so membership is decided
// the way a user checks it, in double arithmetic with no tolerance, and every projection
// lands inside by that test.
//
// Each bound also says which face of its set a vertex is on (its sphere, or the sides of its
// box it touches), and restricts a displacement to that face; Active_set.h collects them.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DEVIATION_BOUNDS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DEVIATION_BOUNDS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// |q - c| <= eps as a user computes it: the squared distance against eps^2, and its square
// root against eps (both, since rounding may separate them). Below 0.98 eps^2, where eps^2 is
// a normal number, the square root is within eps whatever the rounding: it is not taken.
inline bool is_in_ball(const double* q, const double* c, double eps)
{
  const double dx = q[0] - c[0], dy = q[1] - c[1], dz = q[2] - c[2];
  const double d2 = dx * dx + dy * dy + dz * dz, eps2 = eps * eps;
  if(d2 <= 0.98 * eps2 && eps2 >= (std::numeric_limits<double>::min)())
    return true;
  return d2 <= eps2 && std::sqrt(d2) <= eps;
}

// The box's side along one axis, [lo, hi] around c of half-extent h >= 0: the closest doubles to
// c -+ h whose difference to c, as computed, is <= h.
inline void box_side(double c, double h, double& lo, double& hi)
{
  lo = c - h;
  hi = c + h;
  while(c - lo > h)
    lo = std::nextafter(lo, c);
  while(hi - c > h)
    hi = std::nextafter(hi, c);
}

// Whether q lies in the box of half-extents h around c, exactly as Box_bound::contains() decides.
inline bool is_in_box(const double* q, const double* c, const double* h)
{
  for(int k = 0; k < 3; ++k)
  {
    double lo, hi;
    box_side(c[k], h[k], lo, hi);
    if(!(lo <= q[k] && q[k] <= hi))
      return false;
  }
  return true;
}

// |d|, without underflow to 0 or overflow to infinity where |d| itself is in range (the
// plain formula first: the careful one is several times slower).
inline double robust_norm(const Eigen::Vector3d& d)
{
  const double r = d.norm();
  return (r > 0 && r < std::numeric_limits<double>::infinity()) ? r : d.stableNorm();
}

// A size per vertex: one value for all of them, or one each.
class Bound_sizes
{
public:
  explicit Bound_sizes(double uniform) : m_uniform(uniform), m_largest(uniform) {}
  explicit Bound_sizes(std::vector<double> per_vertex)
    : m_uniform(0), m_largest(per_vertex.empty() ? 0 : *std::max_element(per_vertex.begin(), per_vertex.end())),
      m_per_vertex(std::move(per_vertex))
  {}

  double operator[](std::size_t i) const { return m_per_vertex.empty() ? m_uniform : m_per_vertex[i]; }
  double largest() const { return m_largest; }

private:
  double m_uniform, m_largest;
  std::vector<double> m_per_vertex;
};

// What the bounds share: the input points, each vertex's size (the radius of its ball, the
// largest half-extent of its box), and the loops over all vertices.
template <typename Bound>
class Deviation_bound_base
{
public:
  Deviation_bound_base(const Points& X0, Bound_sizes size) : m_X0(X0), m_size(std::move(size)) {}

  // Vertex i's size; 0 pins it.
  double size(std::size_t i) const { return m_size[i]; }
  // The largest size of any vertex (the solvers' first step).
  double largest_size() const { return m_size.largest(); }
  const Points& input_points() const { return m_X0; }

  // X = P(X), the closest point of Omega (up to the last bit, which is chosen inwards)
  void project(Points& X) const
  {
    parallel_for_blocks(static_cast<std::size_t>(X.rows()), [&](std::size_t begin, std::size_t end, std::size_t) {
      project_range(X, begin, end);
    });
  }

  // The same for the vertices [begin, end) of X only.
  void project_range(Points& X, std::size_t begin, std::size_t end) const
  {
    for(std::size_t i = begin; i < end; ++i)
      static_cast<const Bound&>(*this).project(X, i);
  }

  // |x_i - x0_i|
  double deviation(const Points& X, std::size_t i) const { return (point(X, i) - point(m_X0, i)).norm(); }

  // The largest Euclidean distance |x_i - x0_i| over all vertices.
  double max_deviation(const Points& X) const
  {
    double d2 = 0;
    for(std::size_t i = 0; i < static_cast<std::size_t>(X.rows()); ++i)
      d2 = (std::max)(d2, (point(X, i) - point(m_X0, i)).squaredNorm());
    return std::sqrt(d2);
  }

protected:
  // The rounding error of vertex i's coordinates, whose set has size `size`.
  double rounding_error(std::size_t i, double size) const
  {
    // constexpr: libstdc++'s denorm_min() converts a long double literal inexactly, which
    // -frounding-math (in every CGAL build) leaves to run time, as x87 code in this loop.
    constexpr double smallest_subnormal = std::numeric_limits<double>::denorm_min();
    return (std::max)(std::numeric_limits<double>::epsilon() * (point(m_X0, i).template lpNorm<Eigen::Infinity>() + size),
                      smallest_subnormal);
  }

  const Points& m_X0;
  Bound_sizes m_size;
};

// |p_i - p0_i| <= r_i
class Ball_bound : public Deviation_bound_base<Ball_bound>
{
public:
  // A vertex on its sphere: the outward unit normal there (zero when r_i is below the
  // rounding error of the coordinates, and the vertex cannot move at all).
  using Face = Eigen::Vector3d;

  Ball_bound(const Points& X0, double eps) : Ball_bound(X0, Bound_sizes(eps)) {}
  Ball_bound(const Points& X0, Bound_sizes radius) : Deviation_bound_base<Ball_bound>(X0, std::move(radius)) {}

  // The bound of the vertices `vertices[k]` alone, as vertex k about X0_part: its ball if
  // moves[k] (X0_part's row then that vertex's row of the input points), else pinned at its row.
  Ball_bound part(const Points& X0_part, const std::vector<Index>& vertices, const std::vector<bool>& moves) const
  {
    std::vector<double> radius(vertices.size(), 0.);
    for(std::size_t k = 0; k < vertices.size(); ++k)
    {
      CGAL_precondition(!moves[k] || point(X0_part, k) == point(m_X0, vertices[k]));
      if(moves[k])
        radius[k] = m_size[vertices[k]];
    }
    return Ball_bound(X0_part, Bound_sizes(std::move(radius)));
  }

  bool contains(const Points& X, std::size_t i) const { return contains_point(X.data() + 3 * i, i); }

  // Whether the point q lies in vertex i's set.
  bool contains_point(const double* q, std::size_t i) const { return is_in_ball(q, m_X0.data() + 3 * i, m_size[i]); }

  // How far the ray q + t n (t >= 0, n a unit vector, q in the set) stays in vertex i's set, up
  // to rounding (Normal_offsets.h checks the end).
  double ray_length(std::size_t i, const Eigen::Vector3d& q, const Eigen::Vector3d& n) const
  {
    const Eigen::Vector3d d = q - point(m_X0, i);
    const double b = d.dot(n), c = d.squaredNorm() - m_size[i] * m_size[i];
    const double root = std::sqrt((std::max)(b * b - c, 0.));
    // t^2 + 2 b t + c = 0, the larger root, without cancellation
    const double t = b > 0 ? -c / (b + root) : root - b;
    return (std::max)(t, 0.);
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
    const double r = robust_norm(d), eps = m_size[i];
    if(r < std::numeric_limits<double>::infinity())
      for(double slack = 0; slack < eps; slack = (slack == 0) ? rounding_error(i, eps) : 2 * slack)
      {
        point(X, i) = c + ((eps - slack) / r) * d;
        if(contains(X, i))
          return;
      }
    point(X, i) = c;
  }

  // Whether vertex i is on its sphere (up to what projection may leave), and then its face.
  bool is_on_boundary(const Points& X, std::size_t i, Face& face) const
  {
    const Eigen::Vector3d d = point(X, i) - point(m_X0, i);
    const double r = robust_norm(d), eps = m_size[i];
    if(r < eps - 8 * rounding_error(i, eps))
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

// |p_ik - c_ik| <= h_ik for each coordinate k, c_i the box's centre (by default p0_i)
class Box_bound : public Deviation_bound_base<Box_bound>
{
public:
  // A vertex on its box: the sides it touches, per coordinate -1 (lower), +1 (upper) or 0.
  using Face = Eigen::Vector3i;

  // The cube of half-side eps around each input point.
  Box_bound(const Points& X0, double eps)
    : Box_bound(X0, [eps](std::size_t) { return Eigen::Vector3d(eps, eps, eps); },
                [&X0](std::size_t i) { return Eigen::Vector3d(point(X0, i)); })
  {
  }

  // Vertex i's box has half-extents `half_extents(i)` (>= 0) around `centre(i)`, both
  // Eigen::Vector3d.
  template <typename HalfExtents, typename Centre>
  Box_bound(const Points& X0, const HalfExtents& half_extents, const Centre& centre)
    : Deviation_bound_base<Box_bound>(X0, Bound_sizes(0)), m_lower(X0.rows(), 3), m_upper(X0.rows(), 3)
  {
    std::vector<double> largest(static_cast<std::size_t>(X0.rows()));
    for(std::size_t i = 0; i < largest.size(); ++i)
    {
      const Eigen::Vector3d h = half_extents(i), c = centre(i);
      largest[i] = h.maxCoeff();
      for(int k = 0; k < 3; ++k)
        box_side(c[k], h[k], m_lower(Eigen::Index(i), k), m_upper(Eigen::Index(i), k));
    }
    m_size = Bound_sizes(std::move(largest));
  }

  // The bound of the vertices `vertices[k]` alone, as vertex k about X0_part: its box if
  // moves[k], else pinned at its row of X0_part.
  Box_bound part(const Points& X0_part, const std::vector<Index>& vertices, const std::vector<bool>& moves) const
  {
    Box_bound bound(X0_part);
    std::vector<double> largest(vertices.size(), 0.);
    for(std::size_t k = 0; k < vertices.size(); ++k)
    {
      const Eigen::Index j = Eigen::Index(k), i = Eigen::Index(vertices[k]);
      bound.m_lower.row(j) = moves[k] ? m_lower.row(i) : X0_part.row(j);
      bound.m_upper.row(j) = moves[k] ? m_upper.row(i) : X0_part.row(j);
      if(moves[k])
        largest[k] = m_size[vertices[k]];
    }
    bound.m_size = Bound_sizes(std::move(largest));
    return bound;
  }

  bool contains(const Points& X, std::size_t i) const { return contains_point(X.data() + 3 * i, i); }

  // Whether the point q lies in vertex i's set.
  bool contains_point(const double* q, std::size_t i) const
  {
    for(std::size_t c = 0; c < 3; ++c)
      if(!(m_lower.data()[3 * i + c] <= q[c] && q[c] <= m_upper.data()[3 * i + c]))
        return false;
    return true;
  }

  // How far the ray q + t n (t >= 0, n a unit vector, q in the set) stays in vertex i's set, up
  // to rounding (Normal_offsets.h checks the end).
  double ray_length(std::size_t i, const Eigen::Vector3d& q, const Eigen::Vector3d& n) const
  {
    double t = std::numeric_limits<double>::infinity();
    for(std::size_t c = 0; c < 3; ++c)
      if(n[Eigen::Index(c)] != 0)
      {
        const double side = n[Eigen::Index(c)] > 0 ? m_upper.data()[3 * i + c] : m_lower.data()[3 * i + c];
        t = (std::min)(t, (side - q[Eigen::Index(c)]) / n[Eigen::Index(c)]);
      }
    return (std::max)(t, 0.);
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
  explicit Box_bound(const Points& X0)
    : Deviation_bound_base<Box_bound>(X0, Bound_sizes(0)), m_lower(X0.rows(), 3), m_upper(X0.rows(), 3)
  {}

  Points m_lower, m_upper; // the box, per coordinate
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_DEVIATION_BOUNDS_H
