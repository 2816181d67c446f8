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
//
// Degenerate triangles. A triangle of zero area has no normal, and near zero its normal turns
// wildly under tiny moves: a hinge containing it has no meaningful dihedral angle, and its
// steep energy would throttle every step of the descent. So:
//  - hinges with a triangle that is degenerate in the input, of doubled area at most 1e-6 of
//    its longest squared edge (an angle of about a micro radian), are left out of the energy.
//    Their vertices are still faired by their other hinges.
//  - the remaining triangles' doubled areas and normals are regularized, so that triangles
//    degenerating during the descent cannot produce a NaN: with N the cross product of two
//    edges, l = sqrt(|N|^2 + delta^2) and n = N / l, delta 1e-9 of the input's mean doubled
//    area. In double, this leaves l and n unchanged on a triangle larger than a tenth of the
//    mean, and changes them by less than 1e-12 relatively on one a thousand times smaller.
//    A triangle collapsing to zero area gets a zero normal instead of an undefined
//    one, and its hinges cost about as much as a bend between unit normals 60 degrees apart.
// The energy and its gradient are then finite on every configuration of the points.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Hinge_mesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Bending_energy
{
public:
  // Relative to the input's mean doubled area.
  static constexpr double area_regularization = 1e-9;
  // Relative to a triangle's longest squared edge.
  static constexpr double degenerate_area = 1e-6;

  // X0: the input points, which fix the regularization and the hinges left out.
  Bending_energy(const Hinge_mesh& mesh, const Points& X0) : m_mesh(mesh), m_scale(unit_scale(X0))
  {
    compute_triangles(X0);
    double sum = 0; // of the unregularized doubled areas, delta being 0 so far
    std::vector<bool> degenerate(m_mesh.triangles.size());
    for(std::size_t f = 0; f < m_mesh.triangles.size(); ++f)
    {
      sum += m_doubled_area[f];
      const auto& v = m_mesh.triangles[f];
      double longest = 0;
      for(int k = 0; k < 3; ++k)
        longest = (std::max)(longest, (point(*m_points, v[k]) - point(*m_points, v[(k + 1) % 3])).squaredNorm());
      degenerate[f] = !(m_doubled_area[f] > degenerate_area * longest);
    }
    m_delta = m_mesh.triangles.empty() ? 0 : area_regularization * sum / double(m_mesh.triangles.size());
    for(const Hinge& h : m_mesh.hinges)
      if(!degenerate[h.f[0]] && !degenerate[h.f[1]])
        m_hinges.push_back(h);
  }

  // False if the input has no area at all (in double): then the regularization vanishes
  // and the energy is undefined.
  bool is_defined() const { return m_delta * m_delta > 0; }

  // The number of hinges left out because of a degenerate triangle.
  std::size_t number_of_degenerate_hinges() const { return m_mesh.hinges.size() - m_hinges.size(); }

  double value(const Points& X)
  {
    compute_triangles(X);
    double energy = 0;
    for(const Hinge& h : m_hinges)
      energy += Hinge_terms(*this, h).energy();
    return energy;
  }

  // Returns the energy and writes its gradient to G (resized to X's shape). With
  // L = |e|^2, S = l1 + l2 and C = |n1 - n2|^2 / 2 (l and n the regularized doubled areas and
  // normals of the triangles T1 = (p0, p1, p2) and T2 = (p1, p0, p3) of a hinge), a hinge
  // contributes (3/2) L C / S, and
  //   dE = (3/2) (C/S dL + L/S dC - L C/S^2 dS).
  // For a triangle, dl = <n, dN> and dn = (dN - n <n, dN>) / l, so dS and dC are linear in the
  // triangles' dN: each hinge adds a vector coefficient a to each of its two triangles, with
  // dE = sum <a, dN>. Moving vertex k of a triangle by d changes N by d x (p_(k+1) - p_(k+2)),
  // so the triangle then adds a x (p_(k+2) - p_(k+1)) to the gradient at that vertex.
  double value_and_gradient(const Points& X, Points& G)
  {
    compute_triangles(X);
    const std::size_t nt = m_mesh.triangles.size();
    m_coefficient.setZero(static_cast<Eigen::Index>(nt), 3);
    G.setZero(X.rows(), 3);

    double energy = 0;
    for(const Hinge& h : m_hinges)
    {
      const Hinge_terms t(*this, h);
      energy += t.energy();
      const double kS = -1.5 * t.L * t.C / (t.S * t.S), kC = 1.5 * t.L / t.S, kL = 1.5 * t.C / t.S;
      const Eigen::Vector3d d = t.n1 - t.n2;
      point(m_coefficient, h.f[0]) += (kC / t.l1) * (d - d.dot(t.n1) * t.n1) + kS * t.n1;
      point(m_coefficient, h.f[1]) -= (kC / t.l2) * (d - d.dot(t.n2) * t.n2) - kS * t.n2;
      point(G, h.v[0]) -= 2 * kL * t.e;
      point(G, h.v[1]) += 2 * kL * t.e;
    }

    for(std::size_t f = 0; f < nt; ++f)
    {
      const auto& v = m_mesh.triangles[f];
      const Eigen::Vector3d a = point(m_coefficient, f);
      for(int k = 0; k < 3; ++k)
        point(G, v[k]) += a.cross(point(*m_points, v[(k + 2) % 3]) - point(*m_points, v[(k + 1) % 3]));
    }
    if(m_scale != 1)
      G *= m_scale; // back from the scaled points: E(s X) = E(X)
    return energy;
  }

private:
  // The scaled points s X, and the regularized doubled area l and normal n of every
  // triangle.
  void compute_triangles(const Points& X)
  {
    if(m_scale == 1)
      m_points = &X;
    else
    {
      m_scaled.noalias() = m_scale * X;
      m_points = &m_scaled;
    }
    const std::size_t nt = m_mesh.triangles.size();
    m_normal.resize(static_cast<Eigen::Index>(nt), 3);
    m_doubled_area.resize(nt);
    for(std::size_t f = 0; f < nt; ++f)
    {
      const auto& v = m_mesh.triangles[f];
      const Eigen::Vector3d p0 = point(*m_points, v[0]);
      const Eigen::Vector3d N = (point(*m_points, v[1]) - p0).cross(point(*m_points, v[2]) - p0);
      const double l = std::sqrt(N.squaredNorm() + m_delta * m_delta);
      m_doubled_area[f] = l;
      point(m_normal, f) = l > 0 ? Eigen::Vector3d(N / l) : Eigen::Vector3d::Zero();
    }
  }

  struct Hinge_terms
  {
    Eigen::Vector3d e, n1, n2;
    double l1, l2, L, S, C;

    Hinge_terms(const Bending_energy& E, const Hinge& h)
      : e(point(*E.m_points, h.v[1]) - point(*E.m_points, h.v[0])), n1(point(E.m_normal, h.f[0])),
        n2(point(E.m_normal, h.f[1])), l1(E.m_doubled_area[h.f[0]]), l2(E.m_doubled_area[h.f[1]]),
        L(e.squaredNorm()), S(l1 + l2), C(0.5 * (n1 - n2).squaredNorm())
    {}

    double energy() const { return 1.5 * L * C / S; }
  };

  const Hinge_mesh& m_mesh;
  std::vector<Hinge> m_hinges; // those of m_mesh without a degenerate triangle
  double m_scale, m_delta = 0;
  // recomputed at each evaluation: the scaled points (X itself when the scale is 1), and per
  // triangle
  const Points* m_points = nullptr;
  Points m_scaled, m_normal, m_coefficient;
  std::vector<double> m_doubled_area;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
