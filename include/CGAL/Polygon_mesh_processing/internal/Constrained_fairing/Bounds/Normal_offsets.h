// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Normal offsets: each vertex moves only along one line, through its start s_i in the
// direction n_i of the surface normal there, and within its bound; the fairing minimizes over
// the offsets t_i of x_i = s_i + t_i n_i. A vertex given no direction moves freely in its set.
//
// The promise: every point a segment admits is one the bound admits, by the bound's own test
// (Deviation_bounds.h). The segment is the part of the line inside the bound's set, its ends
// found in double and checked by that test, and every projection lands inside by it.
//
// Why: the bending energy is stiff across the surface and soft along it, and the softer the
// finer the mesh (doc/design_notes.md, "Iterations that grow with the mesh"). The vertices'
// sliding along the surface is what made the iterations grow with the mesh, and what it gains
// in energy it takes from the surface's accuracy: on the noisy bunny, free vertices end 1.5
// to 1.6 times as far from the clean surface as the offsets' (see the manual). On the segments
// the quasi-Newton method converges on the shape in iterations that do not grow with the mesh.
//
// The objective's gradient is restricted to the directions (Normal_offset_objective), so that
// the quasi-Newton pairs learn the curvature of the offsets alone: the gradient's part along
// the surface, which no step may follow, would otherwise fill them.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_OFFSETS_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_OFFSETS_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Bound>
class Normal_offset_bound
{
public:
  // A vertex on its segment: its direction and the end it is at (-1, +1, or 0 for neither);
  // a free vertex: the face of its bound's set.
  struct Face
  {
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    int end = 0;
    bool free = false;
    typename Bound::Face inner = Bound::Face::Zero();
  };

  // S: the starts, each inside its set of `bound`; N: unit directions, or zero for a free
  // vertex.
  Normal_offset_bound(const Bound& bound, const Points& S, Points N)
    : m_bound(bound), m_start(S), m_direction(std::move(N))
  {}

  bool is_free(std::size_t i) const { return point(m_direction, i).isZero(); }
  const Points& directions() const { return m_direction; }
  double size(std::size_t i) const { return m_bound.size(i); }
  double largest_size() const { return m_bound.largest_size(); }
  const Points& input_points() const { return m_bound.input_points(); }
  bool contains(const Points& X, std::size_t i) const { return m_bound.contains(X, i); }

  void project(Points& X) const
  {
    parallel_for_blocks(static_cast<std::size_t>(X.rows()), [&](std::size_t begin, std::size_t end, std::size_t) {
      project_range(X, begin, end);
    });
  }

  void project_range(Points& X, std::size_t begin, std::size_t end) const
  {
    for(std::size_t i = begin; i < end; ++i)
      project(X, i);
  }

  // The closest point of the segment (of the set, for a free vertex): the offset clamped to
  // the segment's ends, then shortened while rounding leaves s + t n outside the set; the start,
  // which is inside, at worst.
  void project(Points& X, std::size_t i) const
  {
    if(is_free(i))
    {
      m_bound.project(X, i);
      return;
    }
    const Eigen::Vector3d s = point(m_start, i), n = point(m_direction, i);
    double t = (point(X, i) - s).dot(n);
    point(X, i) = s + t * n;
    if(m_bound.contains(X, i))
      return;
    t = t > 0 ? (std::min)(t, segment_end(i, 1)) : (std::max)(t, -segment_end(i, -1));
    point(X, i) = s + shortened(i, t) * n;
  }

  // A vertex on a segment is always on a face of it (a segment has no interior): the line,
  // or an end.
  bool is_on_boundary(const Points& X, std::size_t i, Face& face) const
  {
    face.free = is_free(i);
    if(face.free)
      return m_bound.is_on_boundary(X, i, face.inner);
    face.direction = point(m_direction, i);
    // only the end on the offset's side can be reached
    const double t = (point(X, i) - point(m_start, i)).dot(face.direction), side = t < 0 ? -1. : 1.;
    const bool at_end = side * t >= segment_end(i, side) - end_tolerance * m_bound.size(i);
    face.end = at_end ? int(side) : 0;
    return true;
  }

  // Only an end that the descent direction -g pushes past binds: the quasi-Newton method's
  // directions already lie along the lines, its gradients restricted to them by
  // Normal_offset_objective and its steps taken along them, so that the active set lists the
  // few vertices at a blocking end rather than all of them.
  static bool keep_blocked(Face& face, const Eigen::Vector3d& g)
  {
    if(face.free)
      return Bound::keep_blocked(face.inner, g);
    return face.end * face.direction.dot(g) < 0;
  }

  // Onto the line (an orthogonal projection), or to nothing at a blocking end.
  static void restrict(const Face& face, Eigen::Map<Eigen::Vector3d> v)
  {
    if(face.free)
      Bound::restrict(face.inner, v);
    else if(face.end != 0)
      v.setZero();
    else
      v = face.direction.dot(v) * face.direction;
  }

private:
  // Within this fraction of the bound's size from an end, a vertex is at it.
  static constexpr double end_tolerance = 1e-9;

  // t, or a little less far from the start, so that s + t n is inside the set: rounding may
  // leave it just outside, and the slack grows from the rounding error until it is not.
  double shortened(std::size_t i, double t) const
  {
    const Eigen::Vector3d s = point(m_start, i), n = point(m_direction, i);
    for(double slack = 4 * std::numeric_limits<double>::epsilon(); slack < 1; slack *= 2)
    {
      const Eigen::Vector3d q = s + t * n;
      if(m_bound.contains_point(q.data(), i))
        return t;
      t *= 1 - slack;
    }
    return 0;
  }

  // How far the line goes from the start in the direction sign n (sign = -1 or 1) before it
  // leaves the set, a length: the bound's own estimate, shortened until the end passes the
  // bound's test.
  double segment_end(std::size_t i, double sign) const
  {
    const Eigen::Vector3d s = point(m_start, i), n = sign * point(m_direction, i);
    return sign * shortened(i, sign * m_bound.ray_length(i, s, n));
  }

  const Bound& m_bound;
  Points m_start, m_direction;
};

// The objective seen on the segments: its gradient restricted to each vertex's direction
// (untouched for a free vertex), so that the quasi-Newton pairs learn the curvature of the
// offsets alone.
template <typename Objective, typename Bound>
class Normal_offset_objective
{
public:
  Normal_offset_objective(Objective& objective, const Normal_offset_bound<Bound>& bound)
    : m_objective(objective), m_bound(bound)
  {}

  double value(const Points& X) { return m_objective.value(X); }

  double value_and_gradient(const Points& X, Points& G, Stiffness_and_reach* scales)
  {
    const double e = m_objective.value_and_gradient(X, G, scales);
    const Points& N = m_bound.directions();
    parallel_for_blocks(static_cast<std::size_t>(G.rows()), [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t i = begin; i < end; ++i)
        if(!m_bound.is_free(i))
          point(G, i) = point(N, i).dot(point(G, i)) * point(N, i);
    });
    return e;
  }

private:
  Objective& m_objective;
  const Normal_offset_bound<Bound>& m_bound;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_NORMAL_OFFSETS_H
