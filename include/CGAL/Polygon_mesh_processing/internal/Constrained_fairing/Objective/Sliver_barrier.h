// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A barrier against slivers, added to the objective: with q = 4 sqrt(3) A / (l1^2 + l2^2 + l3^2)
// a triangle's quality (1 when equilateral, 0 when degenerate, A its area, l its edges),
//
//   B = nu * sum over the triangles of q < q0 of  (q0 / (q + q0 / 100) - 1)^2,
//
// q0 about the quality of a needle with a 3 degree angle (6 on label surfaces; both in
// Fairing_settings.h), nu the weight. Why: a hinge of the bending energy costs |e|^2 / A_e times
// its bend, so the energy drops when an edge at a bend shrinks or a triangle there flattens, and
// its minima are full of needles and caps (angles down to 0.0003 degree on the noisy bunny),
// whatever else holds the vertices (a uniform Laplacian term along the surface, an edge length
// term: see the user manual). The barrier leaves every triangle of quality q0 and more alone, so it
// changes neither the shape nor, in our measurements, the bending energy reached; it is finite
// everywhere, 99^2 nu for a triangle of zero area (one shrunk to a point has no shape and no term),
// and smooth where it is nonzero. Like the bending energy it is dimensionless, and like the hinges
// that pull a triangle flat its terms are per triangle, not divided by their number: divided by it,
// the barrier weakened as the mesh was refined, and the smallest angle on the noisy bunny fell from
// 2.7 to 1.3 degrees between 75 k and 1.2 M triangles (2.9 at both per triangle). Triangles that
// are degenerate in the input are left out, as in the bending energy (Mesh_operators.h). Like the
// energy, it is evaluated on the points brought to unit scale (Unit_scaled_points, Points.h): its
// test and its gradient take squares of squared lengths, which in double underflow for coordinates
// under about 1e-76 and overflow over 1e76, where the barrier was otherwise wrong or zero.
//
// Evaluation: a triangle's term and gradient depend on its three points only, so the objective
// evaluates them in the bending energy's tiles (Triangle_terms, Bending_energy.h), where those
// points are at hand; value() and add_gradient() evaluate the barrier on its own.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SLIVER_BARRIER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SLIVER_BARRIER_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>

#include <CGAL/number_type_config.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Sliver_barrier
{
public:
  // The threshold q0 of the needles of apex angle `degrees`: for a given smallest angle, the
  // isosceles needle has the largest quality (q = sqrt(3) / (cot a + cot b + cot c)), so every
  // triangle with a smaller angle has q < q0.
  static double threshold_of_angle(double degrees) { return std::sqrt(3.) * std::sin(degrees * CGAL_PI / 180); }

  Sliver_barrier(const Hinge_mesh& mesh, const Points& X0, double weight, double threshold)
    : m_mesh(mesh), m_weight(weight), m_threshold(threshold), m_unit_scaled(X0)
  {
    if(m_weight > 0)
      m_degenerate = degenerate_triangles(mesh, m_unit_scaled(X0));
  }

  double value(const Points& X)
  {
    const Points& P = m_unit_scaled(X);
    double sum = 0;
    for(std::size_t f = 0; f < m_mesh.triangles.size(); ++f)
      sum += value(Index(f), corners(P, f));
    return sum;
  }

  // Returns B, adds its gradient to G and its Gauss-Newton diagonal to the stiffness.
  double add_gradient(const Points& X, Points& G, Stiffness_and_reach* scales)
  {
    const Points& P = m_unit_scaled(X);
    Points G_scaled = Points::Zero(X.rows(), 3);
    Stiffness_and_reach scales_scaled;
    if(scales)
      scales_scaled.stiffness = Eigen::VectorXd::Zero(X.rows());
    double sum = 0;
    for(std::size_t f = 0; f < m_mesh.triangles.size(); ++f)
      sum += add_gradient(Index(f), m_mesh.triangles[f], corners(P, f), 7, G_scaled, scales ? &scales_scaled : nullptr);
    const double s = m_unit_scaled.scale(); // back from the scaled points
    G += s * G_scaled;
    if(scales)
      scales->stiffness += (s * s) * scales_scaled.stiffness;
    return sum;
  }

  // Triangle f's term, at its points p brought to unit scale (Triangle_terms, Bending_energy.h).
  // The test needs no square root: q < q0 is 12 |N|^2 < q0^2 S^2, N the doubled area vector and
  // S the sum of the squared edges.
  double value(Index f, const std::array<Eigen::Vector3d, 3>& p) const
  {
    double q;
    return is_sliver(f, p, q) ? term(q) : 0;
  }

  // The same, adding its gradient with respect to p, and its Gauss-Newton diagonal, at the
  // corners k of bit k in `corners`: with B_f = w (r - 1)^2 and r = q0 / (q + q0 / 100),
  // dB_f = outer * dr, dr = inner * dq, q = 4 sqrt(3) A / S, dA at vertex k = n x (p_(k+2) -
  // p_(k+1)) / 2, dS = 2 (2 p_k - the others).
  double add_gradient(Index f, const std::array<Index, 3>& v, const std::array<Eigen::Vector3d, 3>& p,
                      unsigned corners, Points& G, Stiffness_and_reach* scales) const
  {
    double q;
    return is_sliver(f, p, q) ? add_sliver_gradient(q, v, p, corners, G, scales) : 0;
  }

private:
  // The gradient of a sliver of quality q, apart from the test, which then inlines in the tiles.
  double add_sliver_gradient(double q, const std::array<Index, 3>& v, const std::array<Eigen::Vector3d, 3>& p,
                             unsigned corners, Points& G, Stiffness_and_reach* scales) const
  {
    const double shifted = q + m_threshold / 100, r = m_threshold / shifted;
    const double outer = 2 * m_weight * (r - 1), inner = -r / shifted;
    const Eigen::Vector3d N = (p[1] - p[0]).cross(p[2] - p[0]);
    const double length = N.norm();
    const Eigen::Vector3d n = length > 0 ? Eigen::Vector3d(N / length) : Eigen::Vector3d::Zero();
    const double A = length / 2, S = squared_edges(p);
    for(std::size_t k = 0; k < 3; ++k)
    {
      if(!(corners & (1u << k)))
        continue;
      const Eigen::Vector3d& a = p[(k + 1) % 3];
      const Eigen::Vector3d& b = p[(k + 2) % 3];
      const Eigen::Vector3d dA = 0.5 * n.cross(b - a), dS = 2 * (2 * p[k] - a - b);
      const Eigen::Vector3d dq = 4 * std::sqrt(3.) * (S * dA - A * dS) / (S * S);
      point(G, v[k]) += outer * inner * dq;
      if(scales)
        scales->stiffness[static_cast<Eigen::Index>(v[k])] += 2 * m_weight * inner * inner * dq.squaredNorm();
    }
    return term(q);
  }

  std::array<Eigen::Vector3d, 3> corners(const Points& P, std::size_t f) const
  {
    const auto& t = m_mesh.triangles[f];
    return {point(P, t[0]), point(P, t[1]), point(P, t[2])};
  }

  static double squared_edges(const std::array<Eigen::Vector3d, 3>& p)
  {
    return (p[1] - p[0]).squaredNorm() + (p[2] - p[1]).squaredNorm() + (p[0] - p[2]).squaredNorm();
  }

  // Whether triangle f is a sliver left in the barrier, and then its quality q.
  bool is_sliver(Index f, const std::array<Eigen::Vector3d, 3>& p, double& q) const
  {
    if(m_weight == 0)
      return false;
    const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0];
    const double S = a.squaredNorm() + b.squaredNorm() + (b - a).squaredNorm();
    const double N2 = a.cross(b).squaredNorm();
    if(!(12 * N2 < m_threshold * m_threshold * S * S) || m_degenerate[f])
      return false;
    q = 2 * std::sqrt(3.) * std::sqrt(N2) / squared_edges(p);
    return true;
  }

  double term(double q) const
  {
    const double r = m_threshold / (q + m_threshold / 100);
    return m_weight * (r - 1) * (r - 1);
  }

  const Hinge_mesh& m_mesh;
  double m_weight; // nu
  double m_threshold; // q0
  Unit_scaled_points m_unit_scaled;
  std::vector<bool> m_degenerate; // in the input, when the weight is not 0
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SLIVER_BARRIER_H
