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
// Evaluation: each block of triangles lists its slivers in parallel, then their terms are
// summed and their gradients added in triangle order, so that results do not depend on the
// number of threads.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SLIVER_BARRIER_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SLIVER_BARRIER_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Hinge_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Mesh_operators.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Parallel_for.h>

#include <CGAL/number_type_config.h>

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

  double value(const Points& X) { return evaluate(X, nullptr, nullptr); }

  // Returns B, adds its gradient to G and its Gauss-Newton diagonal to the stiffness.
  double add_gradient(const Points& X, Points& G, Stiffness_and_reach* scales) { return evaluate(X, &G, scales); }

private:
  // The test needs no square root: q < q0 is 12 |N|^2 < q0^2 S^2, N the doubled area vector and
  // S the sum of the squared edges.
  double evaluate(const Points& unscaled, Points* G, Stiffness_and_reach* scales)
  {
    if(m_weight == 0)
      return 0;
    const Points& X = m_unit_scaled(unscaled);
    const std::size_t nt = m_mesh.triangles.size();
    m_slivers.resize(number_of_blocks(nt));
    parallel_for_blocks(nt, [&](std::size_t begin, std::size_t end, std::size_t block) {
      std::vector<Index>& slivers = m_slivers[block];
      slivers.clear();
      for(std::size_t f = begin; f < end; ++f)
      {
        const auto& t = m_mesh.triangles[f];
        const Eigen::Vector3d a = point(X, t[1]) - point(X, t[0]), b = point(X, t[2]) - point(X, t[0]);
        const double S = a.squaredNorm() + b.squaredNorm() + (b - a).squaredNorm();
        if(12 * a.cross(b).squaredNorm() < m_threshold * m_threshold * S * S && !m_degenerate[f])
          slivers.push_back(static_cast<Index>(f));
      }
    });
    double sum = 0;
    for(const std::vector<Index>& slivers : m_slivers)
      for(Index f : slivers)
      {
        const double q = quality(X, f), shifted = q + m_threshold / 100, r = m_threshold / shifted;
        sum += m_weight * (r - 1) * (r - 1);
        if(G)
          add_triangle_gradient(X, f, 2 * m_weight * (r - 1), -r / shifted, *G, scales);
      }
    return sum;
  }

  // S, the sum of triangle f's squared edges.
  double squared_edges(const Points& X, std::size_t f) const
  {
    const auto& t = m_mesh.triangles[f];
    return (point(X, t[1]) - point(X, t[0])).squaredNorm() + (point(X, t[2]) - point(X, t[1])).squaredNorm() +
           (point(X, t[0]) - point(X, t[2])).squaredNorm();
  }

  double quality(const Points& X, std::size_t f) const
  {
    return 2 * std::sqrt(3.) * area_normal(m_mesh, X, f).norm() / squared_edges(X, f);
  }

  // With B_f = w (r - 1)^2 and r = q0 / (q + q0 / 100): dB_f = outer * dr, dr = inner * dq,
  // q = 4 sqrt(3) A / S, dA at vertex k = n x (p_(k+2) - p_(k+1)) / 2, dS = 2 (2 p_k - the others).
  // At the scaled points s X, back to X: s times the gradient, s^2 times the stiffness.
  void add_triangle_gradient(const Points& X, std::size_t f, double outer, double inner, Points& G,
                             Stiffness_and_reach* scales) const
  {
    const auto& t = m_mesh.triangles[f];
    const Eigen::Vector3d p[3] = {point(X, t[0]), point(X, t[1]), point(X, t[2])};
    const Eigen::Vector3d N = area_normal(m_mesh, X, f);
    const double length = N.norm();
    const Eigen::Vector3d n = length > 0 ? Eigen::Vector3d(N / length) : Eigen::Vector3d::Zero();
    const double A = length / 2, S = squared_edges(X, f), s = m_unit_scaled.scale();
    for(int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d& a = p[(k + 1) % 3];
      const Eigen::Vector3d& b = p[(k + 2) % 3];
      const Eigen::Vector3d dA = 0.5 * n.cross(b - a), dS = 2 * (2 * p[k] - a - b);
      const Eigen::Vector3d dq = 4 * std::sqrt(3.) * (S * dA - A * dS) / (S * S);
      point(G, t[k]) += s * outer * inner * dq;
      if(scales)
        scales->stiffness[static_cast<Eigen::Index>(t[k])] += s * s * 2 * m_weight * inner * inner * dq.squaredNorm();
    }
  }

  const Hinge_mesh& m_mesh;
  double m_weight; // nu
  double m_threshold; // q0
  Unit_scaled_points m_unit_scaled;
  std::vector<bool> m_degenerate; // in the input, when the weight is not 0
  std::vector<std::vector<Index> > m_slivers; // per block of triangles
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_SLIVER_BARRIER_H
