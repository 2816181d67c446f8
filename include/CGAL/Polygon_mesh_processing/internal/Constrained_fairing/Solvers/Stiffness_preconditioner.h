// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quasi-Newton method's preconditioner: the inverse of the diagonal K of the vertices'
// stiffness along the surface normal (Stiffness_and_reach::stiffness, the Gauss-Newton diagonal of
// the energy's Hessian), the same for a vertex's three coordinates. On noisy scans the
// stiffness ranges over orders of magnitude (small and needle triangles are stiff); scaling by
// it keeps the few stiff vertices from dictating the step of all the others. Being a positive
// multiple of the identity per vertex, it commutes with the active set's restriction.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STIFFNESS_PRECONDITIONER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STIFFNESS_PRECONDITIONER_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// D = gamma K^-1 R, vertex by vertex; R in double or single precision, and may be D itself. A
// vertex with no stiffness is in no hinge: it stays.
template <typename R>
void apply_inverse_stiffness(const Stiffness_and_reach& scales, const R& r, Points& D, double gamma = 1)
{
  D.resize(r.rows(), 3);
  parallel_for_blocks(static_cast<std::size_t>(r.rows()), [&](std::size_t begin, std::size_t end, std::size_t) {
    for(std::size_t i = begin; i < end; ++i)
    {
      const auto row = static_cast<Eigen::Index>(i);
      const double k = scales.stiffness[row];
      D.row(row) = k > 0 ? Eigen::RowVector3d(r.row(row).template cast<double>() / k) : Eigen::RowVector3d::Zero();
      if(gamma != 1)
        point(D, i) = gamma * point(D, i);
    }
  });
}

// <R, K^-1 R> over the rows [begin, end) (a block of Parallel_for.h), with the same rule: a vertex
// with no stiffness adds nothing.
template <typename R>
double inverse_stiffness_norm2_rows(const Eigen::VectorXd& stiffness, const R& r, std::size_t begin, std::size_t end)
{
  double sum = 0;
  for(std::size_t i = begin; i < end; ++i)
  {
    const auto row = static_cast<Eigen::Index>(i);
    const double k = stiffness[row];
    if(k > 0)
      sum += r.row(row).template cast<double>().squaredNorm() / k;
  }
  return sum;
}

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STIFFNESS_PRECONDITIONER_H
