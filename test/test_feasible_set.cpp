// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feasible set: projected points satisfy the bound exactly in double arithmetic, as a
// user checks it, for coordinates and tolerances of very different magnitudes; projection is
// the nearest point; restricting a direction to the face keeps it tangent.

#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/internal/Constrained_fairing/Feasible_set.h>

namespace CF = CGAL::Polygon_mesh_processing::internal::Constrained_fairing;
using Bound = CGAL::Polygon_mesh_processing::Deviation_bound;
using test::Point;

Point row(const CF::Points& X, Eigen::Index i) { return Point(X(i, 0), X(i, 1), X(i, 2)); }

// The user's checks, on CGAL points.
bool user_ball_check(const Point& p, const Point& p0, double eps)
{
  const double d2 = CGAL::squared_distance(p, p0);
  return d2 <= eps * eps && std::sqrt(d2) <= eps;
}

bool user_box_check(const Point& p, const Point& p0, double eps)
{
  return std::abs(p.x() - p0.x()) <= eps && std::abs(p.y() - p0.y()) <= eps && std::abs(p.z() - p0.z()) <= eps;
}

void check_projection(Bound shape)
{
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1), exponent(-9, 0);
  std::size_t moved = 0, on_face = 0;
  for(double magnitude : {1e-3, 1.0, 1e3, 1e6})
  {
    const Eigen::Index n = 2000;
    CF::Points X0(n, 3), X(n, 3);
    const double eps = magnitude * std::pow(10., exponent(rng));
    for(Eigen::Index i = 0; i < n; ++i)
      for(int c = 0; c < 3; ++c)
      {
        X0(i, c) = magnitude * u(rng);
        // from well inside to far outside the bound
        X(i, c) = X0(i, c) + eps * 3 * u(rng) * (i % 3 == 0 ? 1e-3 : 1.0);
      }
    const CF::Points before = X;
    const CF::Feasible_set omega(X0, eps, shape);
    omega.project(X);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const Point p = row(X, i), p0 = row(X0, i), q = row(before, i);
      const bool inside = shape == Bound::BALL ? user_ball_check(p, p0, eps) : user_box_check(p, p0, eps);
      CHECK(inside);
      CHECK(omega.contains(X, static_cast<std::size_t>(i)));
      const bool was_inside = shape == Bound::BALL ? user_ball_check(q, p0, eps) : user_box_check(q, p0, eps);
      if(was_inside)
      {
        CHECK(p == q); // feasible points do not move
        continue;
      }
      ++moved;
      // nearest point of the set, up to rounding of the coordinates
      const double slack = 64 * std::numeric_limits<double>::epsilon() * (magnitude + eps);
      if(shape == Bound::BALL)
      {
        const Point exact = p0 + (q - p0) * (eps / std::sqrt(CGAL::squared_distance(q, p0)));
        CHECK(std::sqrt(CGAL::squared_distance(p, exact)) <= slack);
      }
      else
        for(int c = 0; c < 3; ++c)
          CHECK(std::abs(p[c] - std::clamp(q[c], p0[c] - eps, p0[c] + eps)) <= slack);

      // A projected point is on the face: a restricted direction does not leave it.
      CF::Points V = CF::Points::Zero(n, 3);
      V.row(i) << u(rng), u(rng), u(rng);
      omega.restrict_to_face(X, V);
      const Eigen::Vector3d d = (X.row(i) - X0.row(i)).transpose();
      if(shape == Bound::BALL)
        CHECK(std::abs(V.row(i).dot(d)) <= 1e-9 * V.row(i).norm() * d.norm());
      else
        for(int c = 0; c < 3; ++c)
          if(X(i, c) != before(i, c))
            CHECK(V(i, c) == 0);
      ++on_face;
    }
  }
  CHECK(moved > 1000);
  CHECK(on_face == moved);
}

void check_max_deviation()
{
  CF::Points X0 = CF::Points::Zero(3, 3), X = X0;
  X.row(1) << 0, 3, 4;
  const CF::Feasible_set omega(X0, 10, Bound::BALL);
  CHECK(omega.max_deviation(X) == 5);
}

int main()
{
  check_projection(Bound::BALL);
  check_projection(Bound::BOX);
  check_max_deviation();
  return test::report("test_feasible_set");
}
