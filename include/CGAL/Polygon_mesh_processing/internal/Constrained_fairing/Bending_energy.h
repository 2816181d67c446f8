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
  double value(const Points& X) const
  {
    double energy = 0;
    for(const Hinge& h : m_mesh.hinges)
    {
      const Stencil s(X, h);
      if(!s.is_regular())
        return std::numeric_limits<double>::infinity();
      energy += s.energy();
    }
    return energy;
  }

  // Returns the energy and writes its gradient to G (resized to X's shape).
  double value_and_gradient(const Points& X, Points& G) const
  {
    G.setZero(X.rows(), 3);
    double energy = 0;
    for(const Hinge& h : m_mesh.hinges)
    {
      const Stencil s(X, h);
      if(!s.is_regular())
      {
        G.setConstant(std::numeric_limits<double>::quiet_NaN());
        return std::numeric_limits<double>::infinity();
      }
      energy += s.energy();
      s.add_gradient(h, G);
    }
    return energy;
  }

private:
  // One hinge: the edge e = p1 - p0, the triangles T1 = (p0, p1, p2) and T2 = (p1, p0, p3),
  // their doubled areas l1, l2 (the norms of their cross products) and unit normals n1, n2.
  // With L = |e|^2, S = l1 + l2 = 2 A_e and C = |n1 - n2|^2 / 2 the hinge energy is
  // (3/2) L C / S.
  struct Stencil
  {
    Eigen::Vector3d p0, p1, p2, p3, e, n1, n2;
    double l1, l2, L, S, C;

    Stencil(const Points& X, const Hinge& h)
      : p0(point(X, h.v[0])), p1(point(X, h.v[1])), p2(point(X, h.v[2])), p3(point(X, h.v[3])),
        e(p1 - p0)
    {
      n1 = e.cross(p2 - p0);
      n2 = (p3 - p1).cross(e);
      l1 = n1.norm();
      l2 = n2.norm();
      n1 /= l1;
      n2 /= l2;
      L = e.squaredNorm();
      S = l1 + l2;
      C = 0.5 * (n1 - n2).squaredNorm();
    }

    bool is_regular() const { return l1 > 0 && l2 > 0; }

    double energy() const { return 1.5 * L * C / S; }

    // dE = (3/2) (C/S dL + L/S dC - L C/S^2 dS), where for a vertex a of triangle T with
    // opposite edge vector o (the previous vertex minus the next one, in T's orientation):
    //   d l / d a       = n x o                      (l: T's doubled area)
    //   d <n1,n2> / d a = (o . (n x n')) / l * n     (n' the other triangle's normal)
    // and C = 1 - <n1, n2>.
    void add_gradient(const Hinge& h, Points& G) const
    {
      const Eigen::Vector3d m = n1.cross(n2);
      const double kL = 1.5 * C / S, kC = 1.5 * L / S, kS = -1.5 * L * C / (S * S);

      auto add_t1 = [&](std::size_t i, const Eigen::Vector3d& o) {
        point(G, i) += kS * n1.cross(o) - kC * (o.dot(m) / l1) * n1;
      };
      auto add_t2 = [&](std::size_t i, const Eigen::Vector3d& o) {
        point(G, i) += kS * n2.cross(o) + kC * (o.dot(m) / l2) * n2;
      };
      add_t1(h.v[0], p2 - p1);
      add_t1(h.v[1], p0 - p2);
      add_t1(h.v[2], p1 - p0);
      add_t2(h.v[1], p3 - p0);
      add_t2(h.v[0], p1 - p3);
      add_t2(h.v[3], p0 - p1);
      point(G, h.v[0]) -= 2 * kL * e;
      point(G, h.v[1]) += 2 * kL * e;
    }
  };

  const Hinge_mesh& m_mesh;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_BENDING_ENERGY_H
