// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the quasi-Newton method needs to know of each vertex besides the gradient: how stiff
// the objective is along the surface normal there, and how far the vertex may move before one
// of its triangles could flip. The bending energy computes both (Bending_energy.h), the barrier
// and the fidelity term add to the stiffness, the preconditioner and the step limit read them.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STIFFNESS_AND_REACH_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STIFFNESS_AND_REACH_H

#include <Eigen/Core>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

struct Stiffness_and_reach
{
  // along the surface normal: the Gauss-Newton diagonal (see Bending_energy::value_and_gradient())
  Eigen::VectorXd stiffness;
  // the smallest height of the vertex over the opposite edge in its triangles: a move shorter
  // than that cannot flip or collapse one of them
  Eigen::VectorXd reach;

  void swap(Stiffness_and_reach& other)
  {
    stiffness.swap(other.stiffness);
    reach.swap(other.reach);
  }
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_STIFFNESS_AND_REACH_H
