// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The subspace minimization's direction (Section 4, step 2): an approximate solution of
// H_r v_r = -g_r on the face of the feasible set that contains the Cauchy point, by a few
// preconditioned conjugate gradient iterations (a Newton-CG method). "Reduced" is an
// orthogonal projection onto that face (Active_set::restrict). The preconditioner is the
// exact inverse of the unreduced H = S M^-1 S, reduced the same way: two solves with the
// factorization of S and one diagonal scaling, symmetric positive definite on the face.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_REDUCED_NEWTON_DIRECTION_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_REDUCED_NEWTON_DIRECTION_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Bounds/Active_set.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Reduced_newton_direction
{
public:
  // Conjugate gradient iterations stop early once the preconditioned residual fell by this.
  static constexpr double relative_tolerance = 1e-2;

  // Computes V ~ -H_r^-1 g_r on the face `active` for the gradient G, with at most
  // `max_iterations` conjugate gradient iterations. Returns false if the linear solver fails.
  // Adds the iterations done to `iterations`.
  template <typename ActiveSet, typename Hessian>
  bool compute(const Points& G, const ActiveSet& active, Hessian& H, std::size_t max_iterations, Points& V,
               std::size_t& iterations)
  {
    m_r = -G;
    active.restrict(m_r);
    V.setZero(G.rows(), 3);
    if(!precondition(active, H))
      return false;
    m_p = m_z;
    double rz = dot(m_r, m_z);
    const double stop = relative_tolerance * relative_tolerance * rz;
    for(std::size_t k = 0; k < max_iterations && rz > stop; ++k)
    {
      H.apply(m_p, m_q);
      active.restrict(m_q);
      const double pq = dot(m_p, m_q);
      if(!(pq > 0))
        break;
      const double alpha = rz / pq;
      V += alpha * m_p;
      m_r -= alpha * m_q;
      ++iterations;
      if(k + 1 == max_iterations)
        break;
      if(!precondition(active, H))
        return false;
      const double rz_next = dot(m_r, m_z);
      m_p = m_z + (rz_next / rz) * m_p;
      rz = rz_next;
    }
    return true;
  }

private:
  template <typename ActiveSet, typename Hessian>
  bool precondition(const ActiveSet& active, Hessian& H)
  {
    if(!H.apply_inverse(m_r, m_z))
      return false;
    active.restrict(m_z);
    return true;
  }

  Points m_r, m_z, m_p, m_q;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_REDUCED_NEWTON_DIRECTION_H
