// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The discrete bending energy of Wardetzky et al., eq. (1) of Hildebrandt & Polthier (2007):
//
//   E = sum over interior edges e of  3 |e|^2 / (2 A_e) * cos(theta_e / 2)^2,
//
// A_e the summed area of the two triangles at e, theta_e the dihedral angle between them
// (pi when flat). With unit normals n1, n2, cos(theta_e / 2)^2 = (1 - <n1, n2>) / 2, so a
// hinge contributes (3/4) |e|^2 |n1 - n2|^2 / (2 A_e), and that last form keeps full
// relative precision on nearly flat hinges.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>

#include <Eigen/Geometry>

#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Bending_energy
{
public:
  explicit Bending_energy(const Hinge_mesh& mesh) : m_mesh(mesh) {}

  // +infinity as soon as a hinge has a triangle of zero area: its normal is undefined, and a
  // line search must never step there.
  double value(const Points& X)
  {
    compute_triangles(X);
    double energy = 0;
    for(const Hinge& h : m_mesh.hinges)
    {
      if(!is_regular(h))
        return std::numeric_limits<double>::infinity();
      energy += Hinge_terms(*this, X, h).energy();
    }
    return energy;
  }

  // Returns the energy and writes its gradient to G (resized to X's shape). With
  // L = |e|^2, S = l1 + l2 and C = |n1 - n2|^2 / 2 (l the doubled areas, n the unit normals
  // of the triangles T1 = (p0, p1, p2) and T2 = (p1, p0, p3) of a hinge), a hinge contributes
  // (3/2) L C / S, and
  //   dE = (3/2) (C/S dL + L/S dC - L C/S^2 dS).
  // For a vertex a of a triangle T with opposite edge vector o (previous vertex minus next
  // one, in T's orientation) and n' the other triangle's normal:
  //   d l / d a = n x o,    d <n, n'> / d a = (o . (n x n')) / l * n,    C = 1 - <n1, n2>.
  // Both are linear in per-triangle quantities, so each hinge only adds to its triangles'
  // coefficients (a scalar for dS, a vector for dC), and each triangle then spreads them to
  // its vertices once.
  double value_and_gradient(const Points& X, Points& G)
  {
    compute_triangles(X);
    const std::size_t nt = m_mesh.triangles.size();
    m_area_coefficient.assign(nt, 0.);
    m_normal_coefficient.setZero(static_cast<Eigen::Index>(nt), 3);
    G.setZero(X.rows(), 3);

    double energy = 0;
    for(const Hinge& h : m_mesh.hinges)
    {
      if(!is_regular(h))
      {
        G.setConstant(std::numeric_limits<double>::quiet_NaN());
        return std::numeric_limits<double>::infinity();
      }
      const Hinge_terms t(*this, X, h);
      energy += t.energy();
      const double kS = -1.5 * t.L * t.C / (t.S * t.S), kC = 1.5 * t.L / t.S, kL = 1.5 * t.C / t.S;
      const Eigen::Vector3d m = t.n1.cross(t.n2);
      m_area_coefficient[h.f[0]] += kS;
      m_area_coefficient[h.f[1]] += kS;
      point(m_normal_coefficient, h.f[0]) += (kC / t.l1) * m;
      point(m_normal_coefficient, h.f[1]) -= (kC / t.l2) * m;
      point(G, h.v[0]) -= 2 * kL * t.e;
      point(G, h.v[1]) += 2 * kL * t.e;
    }

    for(std::size_t f = 0; f < nt; ++f)
    {
      const auto& v = m_mesh.triangles[f];
      const Eigen::Vector3d n = point(m_normal, f), a = point(m_normal_coefficient, f);
      const double kS = m_area_coefficient[f];
      for(int k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d o = point(X, v[(k + 2) % 3]) - point(X, v[(k + 1) % 3]);
        point(G, v[k]) += kS * n.cross(o) - o.dot(a) * n;
      }
    }
    return energy;
  }

private:
  // Doubled area l and unit normal n of every triangle.
  void compute_triangles(const Points& X)
  {
    const std::size_t nt = m_mesh.triangles.size();
    m_normal.resize(static_cast<Eigen::Index>(nt), 3);
    m_doubled_area.resize(nt);
    for(std::size_t f = 0; f < nt; ++f)
    {
      const auto& v = m_mesh.triangles[f];
      const Eigen::Vector3d p0 = point(X, v[0]);
      const Eigen::Vector3d N = (point(X, v[1]) - p0).cross(point(X, v[2]) - p0);
      m_doubled_area[f] = N.norm();
      point(m_normal, f) = N / m_doubled_area[f];
    }
  }

  bool is_regular(const Hinge& h) const { return m_doubled_area[h.f[0]] > 0 && m_doubled_area[h.f[1]] > 0; }

  struct Hinge_terms
  {
    Eigen::Vector3d e, n1, n2;
    double l1, l2, L, S, C;

    Hinge_terms(const Bending_energy& E, const Points& X, const Hinge& h)
      : e(point(X, h.v[1]) - point(X, h.v[0])), n1(point(E.m_normal, h.f[0])), n2(point(E.m_normal, h.f[1])),
        l1(E.m_doubled_area[h.f[0]]), l2(E.m_doubled_area[h.f[1]]), L(e.squaredNorm()), S(l1 + l2),
        C(0.5 * (n1 - n2).squaredNorm())
    {}

    double energy() const { return 1.5 * L * C / S; }
  };

  const Hinge_mesh& m_mesh;
  // per triangle, recomputed at each evaluation
  Points m_normal, m_normal_coefficient;
  std::vector<double> m_doubled_area, m_area_coefficient;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
