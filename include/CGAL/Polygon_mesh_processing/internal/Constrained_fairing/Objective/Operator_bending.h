// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bending energy of an input without hinges, from an operator form: a Laplacian L, each
// row a point's (a point set's, from its tangent fan, Point_sets/Tangent_fans.h), each point's
// unit normal n_i, and its mass M_i(X), a third of the area at X of the triangles it owns,
//
//   E(X) = sum over the points i of (n_i . (L X)_i)^2 / M_i(X),
//
// the squared mean curvature (L x)_i / M_i along the normal, integrated over the masses; or,
// without normals, of the whole vector, |(L X)_i|^2 / M_i(X). Why along the normal where the
// points move along their normals: on a plane of normal n every x_j - x_i is orthogonal to n,
// so the term vanishes whatever the weights, while the whole vector (L X)_i vanishes there only
// where the points keep the tangential layout the weights were made for; a point moved along a
// normal that is a little off would pay for its tangential shift, which does not change the
// surface. Why the whole vector where the points slide: with 3 n unknowns, the n terms along
// the normals vanish on wrinkled layouts far from any fair surface, while the whole vector
// also holds each point in its neighbours' layout.
// Why the masses move with X while L and the normals stay: with masses fixed at the input,
// E(s X) = s^2 E(X), and a bounded minimizer would shrink every curved surface to the inner
// side of its bound; with the areas at X it is scale-invariant, as the hinges' energy is
// (Bending_energy.h), and only the noise costs. L need not be symmetric (a point's row is its
// own neighbourhood's). Why an operator: an input without triangles has no hinge, while a
// Laplacian with positive weights can be built from neighbours alone (Sharp and Crane, "A
// Laplacian for nonmanifold triangle meshes", SGP 2020, for point clouds); with it, such an
// input brings its bending as one more term of the objective (Objective_terms.h), and the
// solvers, bounds and driver stay as they are.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OPERATOR_BENDING_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OPERATOR_BENDING_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Objective_terms.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// A triangle of the masses: its corners, and the point whose mass its area is a third of.
struct Mass_triangle
{
  std::array<Index, 3> corners;
  Index owner;
};

class Operator_bending final : public Objective_term
{
public:
  using Laplacian = Eigen::SparseMatrix<double>;

  // `laplacian` n x n, its rows' entries summing to zero; `normals` the n unit normals, or none
  // (0 rows) for the whole vector; every nonzero row's point owns a triangle of `masses` of
  // positive area at X0.
  Operator_bending(Laplacian laplacian, Points normals, std::vector<Mass_triangle> masses, const Points& X0)
    : m_L(std::move(laplacian)), m_Lt(m_L.transpose()), m_normals(std::move(normals)), m_triangles(std::move(masses))
  {
    CGAL_precondition(m_L.rows() == m_L.cols() && m_L.rows() == X0.rows() &&
                      (m_normals.rows() == X0.rows() || m_normals.rows() == 0));
    Eigen::VectorXd M;
    masses_at(X0, M);
    m_stiffness = Eigen::VectorXd::Zero(m_L.rows());
    for(Eigen::Index j = 0; j < m_L.outerSize(); ++j)
      for(Laplacian::InnerIterator it(m_L, j); it; ++it)
      {
        CGAL_precondition(M[it.row()] > 0);
        m_stiffness[j] += 2 * it.value() * it.value() / M[it.row()];
      }
  }

  double value(const Points& X) override
  {
    m_curvature.noalias() = m_L * X;
    if(m_normals.rows() > 0)
      m_curvature = m_normals.array().colwise() * (m_curvature.array() * m_normals.array()).rowwise().sum();
    masses_at(X, m_M);
    double sum = 0;
    for(Eigen::Index i = 0; i < X.rows(); ++i)
      if(m_M[i] != 0)
        sum += point(m_curvature, i).squaredNorm() / m_M[i];
    return sum;
  }

  // The gradient 2 L^T (c_i / M_i), c_i = (L X)_i or its part along n_i, less each mass's
  // share: |c_i|^2 / M_i^2 times the gradient of a third of its triangles' areas.
  double add_gradient(const Points& X, Points& G, Stiffness_and_reach* scales) override
  {
    const double energy = value(X);
    Points& scaled = m_scaled;
    Eigen::VectorXd& share = m_share;
    scaled.setZero(X.rows(), 3);
    share.setZero(X.rows());
    for(Eigen::Index i = 0; i < X.rows(); ++i)
      if(m_M[i] != 0)
      {
        point(scaled, i) = point(m_curvature, i) / m_M[i];
        share[i] = point(scaled, i).squaredNorm() / 3;
      }
    m_product.noalias() = m_Lt * scaled; // as a temporary would hold it, bit for bit
    G += 2 * m_product;
    for(const Mass_triangle& t : m_triangles)
    {
      const Eigen::Vector3d a = point(X, t.corners[0]), b = point(X, t.corners[1]), c = point(X, t.corners[2]);
      const Eigen::Vector3d normal = (b - a).cross(c - a);
      const double length = normal.norm();
      if(!(length > 0))
        continue;
      const Eigen::Vector3d unit = normal / length;
      const double s = share[t.owner] / 2;
      point(G, t.corners[0]) -= s * unit.cross(c - b);
      point(G, t.corners[1]) -= s * unit.cross(a - c);
      point(G, t.corners[2]) -= s * unit.cross(b - a);
    }
    if(scales)
      scales->stiffness += m_stiffness;
    return energy;
  }

  bool is_bending() const override { return true; }

private:
  void masses_at(const Points& X, Eigen::VectorXd& M) const
  {
    M.setZero(X.rows());
    for(const Mass_triangle& t : m_triangles)
    {
      const Eigen::Vector3d a = point(X, t.corners[0]), b = point(X, t.corners[1]), c = point(X, t.corners[2]);
      M[t.owner] += (b - a).cross(c - a).norm() / 6;
    }
  }

  Laplacian m_L;
  Laplacian m_Lt; // its transpose, for the gradient
  Points m_normals;
  std::vector<Mass_triangle> m_triangles;
  Eigen::VectorXd m_stiffness; // a bound of the Hessian's diagonal of the quadratic part at X0
  Points m_curvature; // (L X)_i or its part along n_i, at the last value()
  Eigen::VectorXd m_M;
  Points m_scaled;         // the gradient's c_i / M_i, each mass's share of it, and L^T of it:
  Eigen::VectorXd m_share; // kept from one evaluation to the next, not allocated in each
  Points m_product;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_OPERATOR_BENDING_H
