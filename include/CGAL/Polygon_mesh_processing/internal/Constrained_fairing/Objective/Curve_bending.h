// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bending of curves made of edges of the surface (Curve_network.h): the junction lines of a
// multi-label surface, where three or more labels meet, and the creases of a mesh (its feature
// edges):
//
//   C = w * sum over the inner points i of a line of |x_p - 2 x_i + x_n|^2 / l_i^2,
//
// p and n the neighbours of i along its line, l_i the mean length of its two segments in the
// input. Why: the bending energy has no hinge across such a line (a junction line is not an edge
// of any one interface; a crease's hinges are left out so that it stays sharp), so it does not
// see it; left to the surfaces alone a junction line would be pulled into a crease or rounded
// off, and a crease would follow the noise of its points. The second difference fairs it as a
// curve (a straight line, a circle: its turning, not its place), and dividing by l_i^2 makes
// each term dimensionless and scale-invariant, as a hinge of the bending energy is: a line of
// turning angle theta per segment adds w theta^2 per point, as a hinge bent by theta adds about
// 3 theta^2.

#ifndef CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CURVE_BENDING_H
#define CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CURVE_BENDING_H

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Mesh/Points.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Objective_terms.h>
#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Objective/Stiffness_and_reach.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Constrained_fairing {

class Curve_bending final : public Objective_term
{
public:
  // `points[k]` = {p, i, n}: inner point i of a line and its neighbours, in the solver's order;
  // X0 the input points; `weight` the term's, per point of a line, against the bending
  // energy's hinges.
  Curve_bending(const std::vector<std::array<Index, 3> >& points, const Points& X0, double weight)
    : m_points(points), m_coefficient(points.size())
  {
    for(std::size_t k = 0; k < points.size(); ++k)
    {
      const auto& t = points[k];
      const double l = 0.5 * ((point(X0, t[1]) - point(X0, t[0])).norm() + (point(X0, t[2]) - point(X0, t[1])).norm());
      m_coefficient[k] = l > 0 ? weight / (l * l) : 0;
    }
  }

  std::size_t size() const { return m_points.size(); }

  double value(const Points& X) override
  {
    double sum = 0;
    for(std::size_t k = 0; k < m_points.size(); ++k)
      sum += m_coefficient[k] * second_difference(X, k).squaredNorm();
    return sum;
  }

  // Adds the gradient to G and the Gauss-Newton diagonal to the stiffness (the term is
  // quadratic: 2 c per neighbour, 8 c for the inner point, in every direction); returns the value.
  double add_gradient(const Points& X, Points& G, Stiffness_and_reach* scales) override
  {
    double sum = 0;
    for(std::size_t k = 0; k < m_points.size(); ++k)
    {
      const auto& t = m_points[k];
      const double c = m_coefficient[k];
      const Eigen::Vector3d r = second_difference(X, k);
      sum += c * r.squaredNorm();
      point(G, t[0]) += 2 * c * r;
      point(G, t[1]) -= 4 * c * r;
      point(G, t[2]) += 2 * c * r;
      if(scales)
      {
        scales->stiffness[Eigen::Index(t[0])] += 2 * c;
        scales->stiffness[Eigen::Index(t[1])] += 8 * c;
        scales->stiffness[Eigen::Index(t[2])] += 2 * c;
      }
    }
    return sum;
  }

private:
  Eigen::Vector3d second_difference(const Points& X, std::size_t k) const
  {
    const auto& t = m_points[k];
    return point(X, t[0]) - 2 * point(X, t[1]) + point(X, t[2]);
  }

  std::vector<std::array<Index, 3> > m_points;
  std::vector<double> m_coefficient;
};

} // namespace Constrained_fairing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_PMP_INTERNAL_CONSTRAINED_FAIRING_CURVE_BENDING_H
