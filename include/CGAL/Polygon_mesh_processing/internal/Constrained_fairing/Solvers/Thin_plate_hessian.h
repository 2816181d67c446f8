// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The approximation H = S M^-1 S of the bending energy's Hessian (Section 4.1): the Hessian
// of the thin plate energy over the input mesh. S is the cotan stiffness matrix with 0.1 added
// to its diagonal (which removes its kernel, the constants), M the lumped vertex areas. It is
// positive definite, the same for x, y and z, built and factorized once. Both are assembled
// on the points scaled by unit_scale(), as the energy is, and scaled back when applied.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_THIN_PLATE_HESSIAN_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_THIN_PLATE_HESSIAN_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

// SparseLinearSolver: a model of `SparseLinearAlgebraWithFactorTraits_d`.
template <typename SparseLinearSolver>
class Thin_plate_hessian
{
  using Matrix = typename SparseLinearSolver::Matrix;
  using Vector = typename SparseLinearSolver::Vector;

public:
  static constexpr double diagonal_shift = 0.1;

  Thin_plate_hessian(const Hinge_mesh& mesh, const Points& X0, const SparseLinearSolver& solver)
    : m_n(mesh.number_of_vertices), m_scale(unit_scale(X0)), m_A(static_cast<int>(m_n)), m_solver(solver),
      m_b(m_n), m_x(m_n)
  {
    const Points Y0 = m_scale * X0;
    assemble_stiffness(mesh, Y0);
    assemble_mass(mesh, Y0);
  }

  Thin_plate_hessian(const Thin_plate_hessian&) = delete; // the solver may point to m_A

  // Factorizes S through the user's solver. False if the solver fails.
  bool factorize()
  {
    for(int k = 0; k < m_S.outerSize(); ++k)
      for(Eigen::SparseMatrix<double>::InnerIterator it(m_S, k); it; ++it)
        m_A.set_coef(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(it.col()), it.value(), true);
    return m_solver.factor(m_A, m_D);
  }

  // out = S M^-1 S P (M in the mesh's units: s^-2 times the scaled masses)
  void apply(const Points& P, Points& out)
  {
    m_SP.noalias() = m_S * P;
    m_SP = (m_scale * m_inverse_mass).asDiagonal() * m_SP;
    out.noalias() = m_scale * (m_S * m_SP);
  }

  // out = H^-1 R = S^-1 M S^-1 R. False if the solver fails.
  bool apply_inverse(const Points& R, Points& out)
  {
    out.resize(R.rows(), 3);
    for(int c = 0; c < 3; ++c)
    {
      for(std::size_t i = 0; i < m_n; ++i)
        m_b.set(i, R(i, c));
      if(!m_solver.linear_solver(m_b, m_x))
        return false;
      for(std::size_t i = 0; i < m_n; ++i)
        m_b.set(i, m_mass[i] * m_x[i] / (m_D * m_scale));
      if(!m_solver.linear_solver(m_b, m_x))
        return false;
      for(std::size_t i = 0; i < m_n; ++i)
        out(i, c) = m_x[i] / (m_D * m_scale);
    }
    return true;
  }

private:
  void add_edge(std::vector<Eigen::Triplet<double> >& entries, std::size_t a, std::size_t b, double w)
  {
    const int i = static_cast<int>(a), j = static_cast<int>(b);
    entries.emplace_back(i, j, -w);
    entries.emplace_back(j, i, -w);
    entries.emplace_back(i, i, w);
    entries.emplace_back(j, j, w);
  }

  // S_ij = -(cot alpha_ij + cot beta_ij) / 2, S_ii = -sum_j S_ij + 0.1, triangle by triangle.
  // The three cotangents of a triangle share one denominator, its doubled area, which keeps
  // the triangle's 3 x 3 block positive semi-definite. Needle and degenerate triangles would
  // blow it up: the denominator is floored at 1e-6 of the longest squared edge, which scales
  // the whole block down and keeps it semi-definite (S only preconditions, it need not be
  // exact). A triangle whose vertices coincide adds nothing.
  void assemble_stiffness(const Hinge_mesh& mesh, const Points& Y0)
  {
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(12 * mesh.triangles.size() + m_n);
    for(const auto& t : mesh.triangles)
    {
      const Eigen::Vector3d p[3] = {point(Y0, t[0]), point(Y0, t[1]), point(Y0, t[2])};
      const Eigen::Vector3d u[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]}; // u[k] opposite p[k]
      const double longest = (std::max)({u[0].squaredNorm(), u[1].squaredNorm(), u[2].squaredNorm()});
      const double denominator = (std::max)(u[1].cross(u[2]).norm(), 1e-6 * longest);
      if(!(denominator > 0))
        continue;
      for(int k = 0; k < 3; ++k) // the angle at p[k] is between -u[(k+1)%3] and u[(k+2)%3]
        add_edge(entries, t[(k + 1) % 3], t[(k + 2) % 3],
                 -0.5 * u[(k + 1) % 3].dot(u[(k + 2) % 3]) / denominator);
    }
    for(std::size_t i = 0; i < m_n; ++i)
      entries.emplace_back(static_cast<int>(i), static_cast<int>(i), diagonal_shift);
    m_S.resize(static_cast<int>(m_n), static_cast<int>(m_n));
    m_S.setFromTriplets(entries.begin(), entries.end());
  }

  // Lumped (barycentric) masses: a third of each incident triangle's area. A vertex with no
  // area around it (isolated, or only in degenerate triangles) gets the mean mass, so that
  // M stays invertible and in the mesh's units.
  void assemble_mass(const Hinge_mesh& mesh, const Points& Y0)
  {
    m_mass = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m_n));
    for(const auto& t : mesh.triangles)
    {
      const auto p0 = point(Y0, t[0]);
      const double third_area = (point(Y0, t[1]) - p0).cross(point(Y0, t[2]) - p0).norm() / 6;
      for(std::size_t v : t)
        m_mass[static_cast<Eigen::Index>(v)] += third_area;
    }
    const double mean = m_n > 0 ? m_mass.sum() / static_cast<double>(m_n) : 0;
    for(Eigen::Index i = 0; i < m_mass.size(); ++i)
      if(!(m_mass[i] > 0))
        m_mass[i] = mean > 0 ? mean : 1;
    m_inverse_mass = m_mass.cwiseInverse();
  }

  std::size_t m_n;
  double m_scale;
  Eigen::SparseMatrix<double> m_S;
  Eigen::VectorXd m_mass, m_inverse_mass; // of the scaled mesh
  Matrix m_A; // S in the solver's format; a solver may keep a pointer to it
  SparseLinearSolver m_solver;
  typename SparseLinearSolver::NT m_D = 1;
  Vector m_b, m_x;
  Points m_SP; // work buffer of apply()
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_THIN_PLATE_HESSIAN_H
