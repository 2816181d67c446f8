// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The active set at a point X of the feasible set: the vertices on the boundary of their
// bound, each with the face of its set it is on. It is computed once per step, and then
// restricts any number of displacements to that face: a vertex on its sphere moves in the
// tangent plane, a coordinate at a side of its box stays. The restriction is an orthogonal
// projection, so a symmetric positive definite operator restricted to the face stays so.
//
// Two notions of "active" serve the solvers: every vertex on its boundary (the face of Omega
// that contains X, for the Newton method's subspace step), or only those that the descent
// direction -G pushes outwards (the binding constraints, for the quasi-Newton method).

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Points.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

template <typename Bound>
class Active_set
{
public:
  using Face = typename Bound::Face;

  // Every vertex of X on the boundary of its set.
  void compute(const Bound& bound, const Points& X)
  {
    m_active.clear();
    Face face;
    for(std::size_t i = 0; i < static_cast<std::size_t>(X.rows()); ++i)
      if(bound.is_on_boundary(X, i, face))
        m_active.emplace_back(static_cast<Index>(i), face);
  }

  // The vertices of X that the descent direction -G pushes out of their set, with the part
  // of the face that blocks them.
  void compute(const Bound& bound, const Points& X, const Points& G)
  {
    m_active.clear();
    Face face;
    for(std::size_t i = 0; i < static_cast<std::size_t>(X.rows()); ++i)
      if(bound.is_on_boundary(X, i, face) && Bound::keep_blocked(face, point(G, i)))
        m_active.emplace_back(static_cast<Index>(i), face);
  }

  // V restricted to the face: its components that would leave it are removed.
  void restrict(Points& V) const
  {
    for(const auto& a : m_active)
      Bound::restrict(a.second, point(V, a.first));
  }

  std::size_t size() const { return m_active.size(); }

private:
  std::vector<std::pair<Index, Face> > m_active;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_ACTIVE_SET_H
