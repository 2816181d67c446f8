// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bending energy of an input without hinges, from an operator form: a symmetric Laplacian
// L with lumped masses M (a point set's, from its points' neighbourhoods),
//
//   E = sum over the coordinates c of X_c^T L M^-1 L X_c,
//
// the squared mean curvature normal L x / M integrated over the masses: zero on planes, and
// dimensionless and scale-invariant when L is (cotangent weights) and M is an area, as the
// hinges' energy (Bending_energy.h). Why an operator: an input without triangles has no hinge,
// while a Laplacian with positive weights can be built from neighbours alone (Sharp and Crane,
// "A Laplacian for nonmanifold triangle meshes", SGP 2020, for point clouds); with it, such an
// input brings its bending as one more term of the objective (Objective_terms.h), and the
// solvers, bounds and driver stay as they are.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OPERATOR_BENDING_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OPERATOR_BENDING_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Objective_terms.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Operator_bending final : public Objective_term
{
public:
  using Laplacian = Eigen::SparseMatrix<double>;

  // `laplacian` symmetric, n x n; `masses` the n positive lumped masses.
  Operator_bending(Laplacian laplacian, Eigen::VectorXd masses)
    : m_L(std::move(laplacian)), m_inverse_mass(masses.cwiseInverse())
  {
    CGAL_precondition(m_L.rows() == m_L.cols() && m_L.rows() == masses.size());
    CGAL_precondition(masses.minCoeff() > 0);
    m_stiffness = Eigen::VectorXd::Zero(m_L.rows());
    for(Eigen::Index j = 0; j < m_L.outerSize(); ++j)
      for(Laplacian::InnerIterator it(m_L, j); it; ++it)
        m_stiffness[j] += 2 * it.value() * it.value() * m_inverse_mass[it.row()];
  }

  double value(const Points& X) override
  {
    m_LX = m_L * X;
    return (m_LX.array().square().colwise() * m_inverse_mass.array()).sum();
  }

  // The gradient 2 L M^-1 L X; the term is quadratic, its Hessian's diagonal 2 sum_j L_ji^2 / M_j
  // in every direction.
  double add_gradient(const Points& X, Points& G, Stiffness_and_reach* scales) override
  {
    const double energy = value(X);
    const Points scaled = m_inverse_mass.asDiagonal() * m_LX;
    G += 2 * (m_L * scaled);
    if(scales)
      scales->stiffness += m_stiffness;
    return energy;
  }

  bool is_bending() const override { return true; }

private:
  Laplacian m_L;
  Eigen::VectorXd m_inverse_mass;
  Eigen::VectorXd m_stiffness; // the Hessian's diagonal, per coordinate
  Points m_LX;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OPERATOR_BENDING_H
